// The evaluator's `try`/`except`/`else`/`finally` and `raise` (doc/language.md, "Errors and
// try/except"). Errors travel as UserError; `except` looks at the exception each stands for
// (caughtException): errors of commands and the sandbox's limits are never caught.
#include "EvaluatorParts.hpp"

#include "Exceptions.hpp"
#include "messages/Messages.hpp"

namespace stella {

namespace {

// Whether `type` (an exception class or a tuple of them) names the class of `exception`.
bool typeMatches(const Evaluator& ev, const Value& type, const ExceptionObject& exception, const Pos& at) {
  if (type.isTuple()) {
    for (const Value& t : type.items()) {
      if (typeMatches(ev, t, exception, at)) {
        return true;
      }
    }
    return false;
  }
  const auto* cls =
      type.isCallable() ? dynamic_cast<const ExceptionClass*>(type.asCallable().get()) : nullptr;
  if (cls == nullptr) {
    ev.raise(at, "LANG_TYPE.39", {{"repr", type.repr()}});
  }
  return exception.exceptionClass().isSubclassOf(*cls);
}

// An error of a command passing through a `try`: says why its `except` did not catch it (once,
// at the innermost `try`: the note starts with the text of LANG_TRY.mark).
TracedError explainUncaught(const UserError& error, const Pos& tryPos) {
  std::vector<Diagnostic> ds = error.diagnostics();
  const std::string mark = msg::text("LANG_TRY.mark");
  const std::string uncaught = msg::text("LANG_TRY.uncaught", {{"mark", mark}, {"line", tryPos.line}});
  for (const auto& note : ds.front().notes) {
    if (note.rfind(mark, 0) == 0) {
      return TracedError(error, true, nullptr);
    }
  }
  ds.front().withNote(uncaught);
  return TracedError(UserError(std::move(ds)), true, nullptr);
}

} // namespace

Evaluator::Flow Evaluator::execTry(const Stmt& s) {
  Flow flow = Flow::Normal;
  std::exception_ptr pending;
  try {
    bool handled = false;
    try {
      flow = execBlock(s.body);
    } catch (const UserError& error) {
      if (s.handlers.empty()) {
        throw;
      }
      flow = handleError(s, error);
      handled = true;
    }
    if (!handled && flow == Flow::Normal) {
      flow = execBlock(s.orelse);
    }
  } catch (const UserError&) {
    if (s.finalbody.empty()) {
      throw;
    }
    pending = std::current_exception();
  }
  if (!s.finalbody.empty()) {
    Flow after = execBlock(s.finalbody);
    if (after != Flow::Normal) {
      return after; // as in Python, break/continue/return in `finally` drops a pending error
    }
    if (pending) {
      std::rethrow_exception(pending);
    }
  }
  return flow;
}

// Runs the first `except` clause that matches the error (called inside the catch block, so that
// a bare `raise` re-raises it); rethrows the error when none does.
Evaluator::Flow Evaluator::handleError(const Stmt& s, const UserError& error) {
  std::shared_ptr<const ExceptionObject> exception = caughtException(error);
  if (exception == nullptr) {
    const auto* traced = dynamic_cast<const TracedError*>(&error);
    if (traced != nullptr && traced->fromCommand()) {
      throw explainUncaught(error, s.pos);
    }
    throw;
  }
  const Stmt* handler = nullptr;
  for (const auto& h : s.handlers) {
    if (h->exprs.empty() || typeMatches(*this, eval(*h->exprs[0]), *exception, h->exprs[0]->pos)) {
      handler = h.get();
      break;
    }
  }
  if (handler == nullptr) {
    throw;
  }
  if (!handler->name.empty()) {
    bindName(handler->name, Value(std::const_pointer_cast<NativeObject>(
                                std::static_pointer_cast<const NativeObject>(exception))));
  }
  handling_.push_back(std::current_exception());
  struct Pop {
    std::vector<std::exception_ptr>& stack;
    ~Pop() { stack.pop_back(); }
  } pop{handling_};
  Flow flow = execBlock(handler->body);
  if (!handler->name.empty()) { // as in Python 3, the name is unbound at the end of the clause
    if (scope_ != nullptr && !scope_->globalNames.contains(handler->name)) {
      scope_->vars.erase(handler->name);
    } else {
      globals_.erase(handler->name);
    }
  }
  return flow;
}

void Evaluator::execRaise(const Stmt& s) {
  if (s.exprs.empty()) {
    if (handling_.empty()) {
      raise(s.pos, "LANG_RAISE", {});
    }
    std::rethrow_exception(handling_.back());
  }
  const Expr& e = *s.exprs[0];
  Value v = eval(e);
  std::shared_ptr<const ExceptionObject> exception;
  if (v.isCallable()) {
    if (const auto* cls = dynamic_cast<const ExceptionClass*>(v.asCallable().get())) {
      exception = std::make_shared<const ExceptionObject>(findExceptionClass(cls->name()), ValueList{});
    }
  } else if (v.isNative()) {
    exception = std::dynamic_pointer_cast<const ExceptionObject>(v.asNative());
  }
  if (exception == nullptr) {
    raise(e.pos, "LANG_TYPE.40", {{"type_name", v.typeName()}});
  }
  const std::string message = exception->strText();
  const std::string name = exception->exceptionClass().name();
  throw TracedError(UserError(message.empty()
                                  ? msg::make("LANG_RAISE.class", {{"name", name}}, location(s.pos))
                                  : msg::make("LANG_RAISE.class_message",
                                              {{"name", name}, {"message", message}}, location(s.pos))),
                    false, exception);
}

} // namespace stella
