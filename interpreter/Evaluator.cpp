// The evaluator: statements and expressions of a parsed command file, with Python's semantics.
// Command calls go to the CommandHandler with their assignment target; user errors are thrown
// as UserError located at the node being evaluated. The rules are in EvaluatorStatements.cpp,
// EvaluatorImports.cpp, EvaluatorExpressions.cpp and EvaluatorCalls.cpp; freeing cycles in
// EvaluatorCycles.cpp. This file: construction, errors, step budget, module execution.
#include "EvaluatorParts.hpp"

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
    : handler_(handler), sink_(sink), options_(options) {}

void Evaluator::raise(const Pos& pos, const std::string& id, const std::string& message,
                      const std::string& note) const {
  Diagnostic d = Diagnostic::fatal(id, message, location(pos));
  if (!note.empty()) {
    d.withNote(note);
  }
  throw UserError(std::move(d));
}

void Evaluator::countStep(const Pos& pos) {
  if (options_.stepBudget > 0 && ++steps_ > options_.stepBudget) {
    raise(pos, "LANG_LIMIT",
          "the run exceeded its budget of " + std::to_string(options_.stepBudget) + " steps");
  }
}

void Evaluator::defineCommand(const std::string& name) {
  globals_[name] = Value(std::shared_ptr<Callable>(std::make_shared<CommandCallable>(name)));
}

void Evaluator::execModule(const std::shared_ptr<const Module>& module, std::size_t firstStatement) {
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
  module_ = module;
  file_ = module->file;
  lookup_ = lookup;
  return eval(expr);
}

} // namespace stella
