// The evaluator: statements and expressions of a parsed command file, with Python's semantics.
// Command calls go to the CommandHandler with their assignment target; user errors are thrown
// as UserError located at the node being evaluated. The rules are in EvaluatorStatements.cpp,
// EvaluatorImports.cpp, EvaluatorExpressions.cpp and EvaluatorCalls.cpp; freeing cycles in
// EvaluatorCycles.cpp. This file: construction, errors, step budget, module execution.
#include "EvaluatorParts.hpp"

#include "Formatter.hpp"
#include "messages/Messages.hpp"

namespace stella {

namespace {

// A command bound by defineCommand: calling it goes to the CommandHandler.
class CommandCallable : public Callable {
public:
  explicit CommandCallable(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  bool isCommand() const override { return true; }

private:
  std::string name_;
};

} // namespace

Evaluator::Evaluator(CommandHandler* handler, DiagnosticSink* sink, EvaluatorOptions options)
    : handler_(handler), sink_(sink), options_(options), meter_(options.budget) {}

void Evaluator::raise(const Pos& pos, std::string_view key, msg::Args args, const std::string& note) const {
  const Diagnostic d = msg::make(key, args);
  STELLA_ASSERT(d.notes.size() <= 1 && (d.notes.empty() || note.empty()), "one note at most");
  raise(pos, LangError{d.id, d.message, d.notes.empty() ? note : d.notes.front()});
}

void Evaluator::raise(const Pos& pos, const LangError& e) const {
  const std::string& id = e.id;
  const std::string& note = e.note;
  Diagnostic d = Diagnostic::fatal(id, e.message, location(pos));
  if (id == "LANG_BUDGET" && !loops_.empty()) {
    // the loop is the culprit: the error points at it, a note at where the budget ran out
    const RunningLoop& loop = loops_.back();
    const Pos& at = loop.statement != nullptr ? loop.statement->pos : loop.clause->pos;
    d.location = location(at);
    d.withNote(runningLoopNote());
    d.withNote(msg::text("LANG_BUDGET.n1", {{"location", location(pos).str()}}));
  }
  if (!note.empty()) {
    d.withNote(note);
  }
  throw UserError(std::move(d));
}

// "in the for loop `for i in range(10**15)` (line 3), at its turn 24999"
std::string Evaluator::runningLoopNote() const {
  const RunningLoop& loop = loops_.back();
  std::string what;
  int line = 0;
  if (loop.statement != nullptr) {
    const Stmt& s = *loop.statement;
    line = s.pos.line;
    what = s.kind == StmtKind::While ? "the while loop `while " + formatExpression(*s.exprs[0]) + "`"
                                     : "the for loop `for " + formatExpression(*s.exprs[0]) + " in " +
                                           formatExpression(*s.exprs[1]) + "`";
  } else {
    const Expr& c = *loop.clause;
    line = c.pos.line;
    what = "the comprehension `for " + formatExpression(*c.items[0]) + " in " +
           formatExpression(*c.items[1]) + "`";
  }
  return "in " + what + " (line " + std::to_string(line) + "), at its turn " + std::to_string(loop.turns);
}

void Evaluator::countStep(const Pos& pos) {
  try {
    meter_.operation();
  } catch (const LangError& e) {
    raise(pos, e);
  }
}

void Evaluator::defineCommand(const std::string& name) {
  globals_[name] = Value(std::shared_ptr<Callable>(std::make_shared<CommandCallable>(name)));
}

void Evaluator::execModule(const std::shared_ptr<const Module>& module, std::size_t firstStatement) {
  MeterGuard metering(meter_);
  auto savedModule = module_;
  auto savedFile = file_;
  module_ = module;
  file_ = module->file;
  for (std::size_t i = firstStatement; i < module->body.size(); ++i) {
    execStatement(*module->body[i]);
  }
  module_ = savedModule;
  file_ = savedFile;
}

Value Evaluator::evalStandalone(const std::shared_ptr<const Module>& module, const Expr& expr,
                                const std::function<std::optional<Value>(const std::string&)>* lookup) {
  MeterGuard metering(meter_);
  module_ = module;
  file_ = module->file;
  lookup_ = lookup;
  return eval(expr);
}

} // namespace stella
