// The evaluator's calls: argument collection (keywords, *args, **kwargs), method calls, and the
// calls of commands, native functions and user functions.
#include "EvaluatorParts.hpp"
#include "Exceptions.hpp"
#include "Suggest.hpp"
#include "messages/Messages.hpp"

#include <algorithm>

namespace stella {

using evaluation::DepthGuard;

void Evaluator::collectArguments(const Expr& call, std::size_t first, CallArguments& args) {
  for (std::size_t i = first; i < call.items.size(); ++i) {
    const Expr& a = *call.items[i];
    switch (a.kind) {
    case ExprKind::Keyword: {
      const Expr& valueExpr = *a.items[0];
      args.keywords.push_back(KeywordArgument{
          a.text, std::make_shared<const Value>(eval(valueExpr)),
          location(Pos{a.pos.line, a.pos.column, static_cast<int>(a.text.size())}), location(valueExpr.pos)});
      break;
    }
    case ExprKind::Star: {
      Value v = eval(*a.items[0]);
      try {
        for (Value& item : iterableItems(v, options_.limits)) {
          args.positional.push_back(std::move(item));
          args.positionalLocations.push_back(location(a.pos));
        }
      } catch (const LangError& err) {
        raise(a.pos, err);
      }
      break;
    }
    case ExprKind::DoubleStar: {
      Value v = eval(*a.items[0]);
      if (!v.isDict()) {
        raise(a.pos, "LANG_TYPE.37", {{"type_name", v.typeName()}});
      }
      for (const auto& [key, value] : v.asDict()->items) {
        if (!key.isString()) {
          raise(a.pos, "LANG_TYPE.38", {{"type_name", key.typeName()}});
        }
        if (args.find(key.asString()) != nullptr) {
          raise(a.pos, "LANG_ARGS.13", {{"as_string", key.asString()}});
        }
        args.keywords.push_back(KeywordArgument{key.asString(), std::make_shared<const Value>(value),
                                                location(a.pos), location(a.pos)});
      }
      break;
    }
    default:
      args.positional.push_back(eval(a));
      args.positionalLocations.push_back(location(a.pos));
    }
  }
}

Value Evaluator::evalCall(const Expr& e, const std::string& target) {
  const Expr& calleeExpr = *e.items[0];
  // `obj.method(...)` on strings, lists and dicts: call the method directly
  if (calleeExpr.kind == ExprKind::Attribute) {
    Value object = eval(*calleeExpr.items[0]);
    if ((object.isString() || object.isSequence() || object.isDict()) && hasMethod(object, calleeExpr.text)) {
      return evalMethodCall(e, object);
    }
    Value callee = attributeOf(object, calleeExpr.text, calleeExpr.pos);
    CallArguments args;
    args.callLocation = location(calleeExpr.pos);
    collectArguments(e, 1, args);
    return call(callee, args, calleeExpr.pos, target);
  }
  Value callee = eval(calleeExpr);
  CallArguments args;
  args.callLocation = location(calleeExpr.pos);
  collectArguments(e, 1, args);
  return call(callee, args, calleeExpr.pos, target);
}

Value Evaluator::evalMethodCall(const Expr& e, const Value& object) {
  const Expr& calleeExpr = *e.items[0];
  CallArguments args;
  args.callLocation = location(calleeExpr.pos);
  collectArguments(e, 1, args);
  return *callMethod(*this, object, calleeExpr.text, args, calleeExpr.pos);
}

Value Evaluator::call(const Value& callee, const CallArguments& args, const Pos& at,
                      const std::string& target) {
  DepthGuard guard(evalDepth_, options_.maxEvalDepth, *this, at);
  if (callee.isCallable()) {
    const Callable& c = *callee.asCallable();
    if (c.isCommand()) {
      return callCommand(c.name(), args, at, target);
    }
    if (const auto* b = dynamic_cast<const Builtin*>(&c)) {
      return callBuiltin(*this, *b, args, at);
    }
    if (const auto* u = dynamic_cast<const UserFunction*>(&c)) {
      return callUser(*u, args, at);
    }
    if (const auto* n = dynamic_cast<const NativeCallable*>(&c)) {
      return callNative(*n, args, at);
    }
  }
  if (callee.isConcept() && handler_ != nullptr) {
    Value fn = attributeOf(callee, "__call__", at);
    if (fn.isCallable()) {
      return call(fn, args, at);
    }
  }
  if (callee.isConcept()) {
    raise(at, "LANG_CALL.concept", {{"type", callee.typeName()}, {"name", callee.asConcept()->name}});
  }
  raise(at, "LANG_CALL.value", {{"type", callee.typeName()}});
}

void Evaluator::checkNotDestroyed(const Value& v, const Pos& at, int depth) const {
  if (depth > 20) {
    return;
  }
  if (v.isConcept() && v.asConcept()->destroyed) {
    raise(at, "LANG_DESTROYED.4", {{"name", v.asConcept()->name}});
  }
  if (v.isSequence()) {
    for (const Value& item : v.items()) {
      checkNotDestroyed(item, at, depth + 1);
    }
  } else if (v.isFactor()) {
    for (const auto& kw : v.asFactor()->keywords) {
      checkNotDestroyed(*kw.value, at, depth + 1);
    }
  }
}

Value Evaluator::callCommand(const std::string& name, const CallArguments& args, const Pos& at,
                             const std::string& target) {
  if (handler_ == nullptr) {
    raise(at, "LANG_CALL.2", {{"name", name}});
  }
  for (std::size_t i = 0; i < args.positional.size(); ++i) {
    checkNotDestroyed(args.positional[i], at);
  }
  for (const auto& kw : args.keywords) {
    if (kw.name == "reuse") {
      continue;
    }
    try {
      checkNotDestroyed(*kw.value, at);
    } catch (UserError&) {
      Diagnostic d = msg::make("LANG_DESTROYED", {{"name", kw.name}, {"name_2", name}}, kw.valueLocation);
      throw UserError(std::move(d));
    }
  }
  // the memory a command allocates (meshes, matrices, results) is not the language's
  struct CommandMetering {
    WorkMeter& meter;
    explicit CommandMetering(WorkMeter& m) : meter(m) { meter.enterCommand(); }
    ~CommandMetering() { meter.leaveCommand(); }
    CommandMetering(const CommandMetering&) = delete;
    CommandMetering& operator=(const CommandMetering&) = delete;
  };
  Value result;
  try {
    CommandMetering metering(meter_);
    result = handler_->callCommand(name, args, target);
  } catch (const UserError& err) {
    throw TracedError(err, true, nullptr);
  }
  if (handler_->finished()) {
    throw FinishSignal{};
  }
  return result;
}

Value Evaluator::callNative(const NativeCallable& fn, const CallArguments& args, const Pos& at) {
  try {
    return fn.function()(args);
  } catch (const UserError& err) {
    std::vector<Diagnostic> ds = err.diagnostics();
    bool changed = false;
    for (auto& d : ds) {
      if (!d.location.known()) {
        d.location = location(at);
        changed = true;
      } else if (d.location.file != file_ || d.location.line != at.line) {
        d.withNote(msg::text("NOTE.n5", {{"name", fn.name()}, {"location", location(at).str()}}));
        changed = true;
      }
    }
    if (!changed) {
      throw;
    }
    rethrowWith(err, std::move(ds));
  } catch (const LangError& err) {
    raise(at, err);
  }
}

Value Evaluator::callUser(const UserFunction& fn, const CallArguments& args, const Pos& at) {
  if (callDepth_ >= options_.maxCallDepth) {
    raise(at, "LANG_DEPTH.4", {{"max_call_depth", std::to_string(options_.maxCallDepth)}});
  }
  Scope local;
  local.function = true;
  std::string name = fn.name();
  if (fn.lambda != nullptr) {
    std::size_t n = fn.lambda->items.size() - 1;
    if (args.positional.size() != n || !args.keywords.empty()) {
      raise(at, "LANG_ARGS.14",
            {{"n", std::to_string(n)}, {"positional_count", std::to_string(args.positional.size())}});
    }
    for (std::size_t i = 0; i < n; ++i) {
      local.vars[fn.lambda->items[i + 1]->text] = args.positional[i];
    }
  } else {
    const auto& params = fn.def->params;
    std::vector<bool> bound(params.size(), false);
    std::size_t regular = 0;
    int starIndex = -1;
    int starStarIndex = -1;
    for (std::size_t i = 0; i < params.size(); ++i) {
      if (params[i].star == 1) {
        starIndex = static_cast<int>(i);
      } else if (params[i].star == 2) {
        starStarIndex = static_cast<int>(i);
      } else if (starIndex < 0) {
        ++regular;
      }
    }
    ValueList extra;
    for (std::size_t i = 0; i < args.positional.size(); ++i) {
      if (i < regular) {
        local.vars[params[i].name] = args.positional[i];
        bound[i] = true;
      } else if (starIndex >= 0) {
        extra.push_back(args.positional[i]);
      } else {
        raise(at, "LANG_ARGS.15",
              {{"name", name},
               {"regular", std::to_string(regular)},
               {"positional_count", std::to_string(args.positional.size())}});
      }
    }
    if (starIndex >= 0) {
      local.vars[params[static_cast<std::size_t>(starIndex)].name] = Value::tuple(std::move(extra));
      bound[static_cast<std::size_t>(starIndex)] = true;
    }
    auto kwargs = std::make_shared<DictObject>();
    for (const auto& kw : args.keywords) {
      auto it = std::find_if(params.begin(), params.end(),
                             [&](const Param& p) { return p.name == kw.name && p.star == 0; });
      if (it == params.end()) {
        if (starStarIndex >= 0) {
          kwargs->items.emplace_back(Value(kw.name), *kw.value);
          continue;
        }
        std::vector<std::string> names;
        for (const auto& p : params) {
          names.push_back(p.name);
        }
        Diagnostic d = msg::make("LANG_ARGS.6", {{"name", name}, {"name_2", kw.name}},
                                 kw.location.known() ? kw.location : location(at));
        std::string note = suggestionNote(kw.name, names);
        if (!note.empty()) {
          d.withNote(note);
        }
        throw UserError(std::move(d));
      }
      auto index = static_cast<std::size_t>(it - params.begin());
      if (bound[index]) {
        raise(at, "LANG_ARGS.16", {{"name", name}, {"name_2", kw.name}});
      }
      local.vars[kw.name] = *kw.value;
      bound[index] = true;
    }
    if (starStarIndex >= 0) {
      local.vars[params[static_cast<std::size_t>(starStarIndex)].name] = Value(kwargs);
      bound[static_cast<std::size_t>(starStarIndex)] = true;
    }
    for (std::size_t i = 0; i < params.size(); ++i) {
      if (!bound[i]) {
        if (!fn.hasDefault[i]) {
          raise(at, "LANG_ARGS.17", {{"name", name}, {"name_2", params[i].name}});
        }
        local.vars[params[i].name] = fn.defaults[i];
      }
    }
  }
  Scope* savedScope = scope_;
  auto savedModule = module_;
  auto savedFile = file_;
  scope_ = &local;
  module_ = fn.module;
  file_ = fn.module->file;
  ++callDepth_;
  auto restore = [&] {
    --callDepth_;
    scope_ = savedScope;
    module_ = savedModule;
    file_ = savedFile;
  };
  Value result;
  try {
    if (fn.lambda != nullptr) {
      result = eval(*fn.lambda->items[0]);
    } else {
      Flow flow = execBlock(fn.def->body);
      if (flow == Flow::Return) {
        result = std::move(returnValue_);
        returnValue_ = Value();
      }
    }
  } catch (...) {
    restore();
    throw;
  }
  restore();
  return result;
}

} // namespace stella
