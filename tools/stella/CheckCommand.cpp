// `stella check` (validate every command of a file against the catalogue without running
// operators), `stella check --syntax`, the developer dumps, and `stella fmt`.

#include "Commands.hpp"
#include "catalog/Catalog.hpp"
#include "interpreter/Interpreter.hpp"
#include "solver/session/Session.hpp"

#include <fstream>
#include <iostream>
#include <sstream>

namespace stella::cli {

namespace {

class StderrSink : public DiagnosticSink {
public:
  void report(const Diagnostic& d) override {
    if (d.severity == Severity::Info) {
      return; // print() output is not shown by check
    }
    if (d.severity != Severity::Alarm) {
      ++errors;
    }
    std::cerr << formatDiagnostic(d);
  }
  int errors = 0;
};

} // namespace

int check(const CheckArguments& args) {
  try {
    auto source = SourceFile::load(args.file);
    if (args.dumpTokens) {
      std::cout << dumpTokens(source);
      return 0;
    }
    if (args.dumpAst) {
      std::cout << dumpAst(source);
      return 0;
    }
    StderrSink sink;
    if (args.syntaxOnly) {
      bool ok = checkSyntax(source, sink);
      return ok ? 0 : 2;
    }
    std::ostringstream silent;
    SessionOptions options;
    options.executeOperators = false;
    const Catalog& catalog = Catalog::builtin();
    Session session(catalog, silent, silent, options);
    // the result units of a quick run (`stella run FILE.comm`), and those given with --unit
    for (int unit : {6, 8, 80, 81}) {
      session.declareResultUnit(unit);
    }
    for (int unit : args.units) {
      session.declareResultUnit(unit);
    }
    InterpreterOptions budget;
    if (args.maxOperations > 0) {
      budget.operationBudget = args.maxOperations;
    }
    budget.memoryBudget = args.maxMemoryMiB << 20;
    Interpreter interpreter(session, sink, budget);
    for (const auto& name : catalog.commandNames()) {
      interpreter.defineCommand(name);
    }
    RunStatus status = interpreter.run(source);
    bool ok = sink.errors == 0 && status != RunStatus::Failed && status != RunStatus::SyntaxError;
    if (ok) {
      std::cerr << args.file << ": valid\n";
    }
    return ok ? 0 : 2;
  } catch (const UserError& e) {
    for (const auto& d : e.diagnostics()) {
      std::cerr << formatDiagnostic(d);
    }
    return exitInput;
  }
}

int format(const std::string& file, bool inPlace) {
  try {
    std::string text = formatSource(SourceFile::load(file));
    if (inPlace) {
      std::ofstream(file) << text;
    } else {
      std::cout << text;
    }
    return 0;
  } catch (const UserError& e) {
    for (const auto& d : e.diagnostics()) {
      std::cerr << formatDiagnostic(d);
    }
    return 2;
  }
}

} // namespace stella::cli
