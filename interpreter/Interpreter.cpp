// Interpreter: parses a command file, runs it statement by statement through the Evaluator,
// and reports every user error to the DiagnosticSink (never throws them).
#include "Interpreter.hpp"

#include "Evaluator.hpp"
#include "Parser.hpp"
#include "messages/Messages.hpp"

#include <new>

namespace stella {

struct Interpreter::Impl {
  Impl(CommandHandler& h, DiagnosticSink& s, const InterpreterOptions& o)
      : handler(h), sink(s), evaluator(&h, &s, toEvaluatorOptions(o)) {}

  static EvaluatorOptions toEvaluatorOptions(const InterpreterOptions& o) {
    EvaluatorOptions e;
    e.whileIterationCap = o.whileIterationCap;
    e.budget.operations = o.operationBudget;
    e.budget.memoryBytes = o.memoryBudget;
    e.limits.maxSequenceLength = o.maxSequenceLength;
    e.limits.maxStringLength = o.maxStringLength;
    return e;
  }

  CommandHandler& handler;
  DiagnosticSink& sink;
  Evaluator evaluator;
  std::vector<std::shared_ptr<const Module>> modules; // kept alive: functions refer to them
};

Interpreter::Interpreter(CommandHandler& handler, DiagnosticSink& sink, InterpreterOptions options)
    : impl_(std::make_unique<Impl>(handler, sink, options)) {}

Interpreter::~Interpreter() = default;

void Interpreter::defineCommand(const std::string& name) {
  impl_->evaluator.defineCommand(name);
}

void Interpreter::defineGlobal(const std::string& name, Value value) {
  impl_->evaluator.globals()[name] = std::move(value);
}

void Interpreter::defineNative(const std::string& name, NativeFunction fn) {
  impl_->evaluator.globals()[name] = makeNativeFunction(name, std::move(fn));
}

std::optional<Value> Interpreter::global(const std::string& name) const {
  auto& globals = impl_->evaluator.globals();
  auto it = globals.find(name);
  if (it == globals.end()) {
    return std::nullopt;
  }
  return it->second;
}

namespace {

Diagnostic abortDiagnostic(const std::string& message) {
  Diagnostic d = msg::make("INTERNAL", {{"message", message}});
  d.kind = FailureKind::Abort;
  return d;
}

SourceLocation endOfFile(const std::shared_ptr<const SourceFile>& file) {
  int line = std::max(1, file->lineCount());
  return SourceLocation{file, line, static_cast<int>(file->line(line).size()) + 1, 1};
}

} // namespace

RunStatus Interpreter::run(const std::shared_ptr<const SourceFile>& file) {
  ParseResult parsed = parseFile(file);
  if (!parsed.errors.empty() && !errorsOnlyAfterFin(parsed)) {
    for (const auto& d : parsed.errors) {
      impl_->sink.report(d);
    }
    return RunStatus::SyntaxError;
  }
  impl_->modules.push_back(parsed.module);
  try {
    impl_->evaluator.execModule(parsed.module);
  } catch (const FinishSignal&) {
    return RunStatus::Finished;
  } catch (const UserError& e) {
    for (const auto& d : e.diagnostics()) {
      impl_->sink.report(d);
    }
    return RunStatus::Failed;
  } catch (const InternalError& e) {
    impl_->sink.report(abortDiagnostic(e.what()));
    return RunStatus::Failed;
  } catch (const std::bad_alloc&) {
    impl_->sink.report(msg::make("LANG_MEMORY"));
    return RunStatus::Failed;
  } catch (const std::exception& e) {
    impl_->sink.report(abortDiagnostic(msg::text("INTERNAL.unexpected", {{"what", e.what()}})));
    return RunStatus::Failed;
  }
  if (impl_->handler.finished()) {
    return RunStatus::Finished;
  }
  impl_->sink.report(msg::make("LANG_FIN", {}, endOfFile(file)));
  return RunStatus::Completed;
}

} // namespace stella
