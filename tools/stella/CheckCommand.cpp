// `stella check` (validate every command of a file against the catalogue without running
// operators), `stella check --syntax`, the developer dumps, and `stella fmt`.

#include "Commands.hpp"
#include "catalog/Catalog.hpp"
#include "interpreter/Interpreter.hpp"
#include "messages/Messages.hpp"
#include "solver/job/Export.hpp"
#include "solver/session/Session.hpp"

#include <filesystem>

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

// The units of a check: an export's lines, or `--unit N` (a result unit) and `--unit N=FILE` (a
// data unit, read by LIRE_MAILLAGE so that the groups are checked). Returns the command files.
std::vector<std::string> declareUnits(const CheckArguments& args, Session& session) {
  std::vector<std::string> commandFiles;
  if (std::filesystem::path(args.file).extension() == ".export") {
    const Export e = Export::read(args.file);
    for (const ExportEntry& entry : e.entries) {
      if (entry.directory || entry.unit <= 0) {
        continue;
      }
      if (entry.result) {
        session.declareResultUnit(entry.unit);
      }
      if (entry.data && entry.type != "comm") {
        session.declareUnit(entry.unit, entry.path);
      }
    }
    for (const ExportEntry* comm : e.commandFiles()) {
      commandFiles.push_back(comm->path.string());
    }
  } else {
    commandFiles.push_back(args.file);
    for (int unit : {6, 8, 80, 81}) { // the result units of a quick run (`stella run FILE.comm`)
      session.declareResultUnit(unit);
    }
  }
  for (const std::string& u : args.units) {
    const auto equal = u.find('=');
    int unit = 0;
    try {
      unit = std::stoi(u.substr(0, equal));
    } catch (const std::exception&) {
      unit = 0;
    }
    if (unit < 1 || unit > 99) {
      throw UserError(msg::make("CLI_1", {{"u", u}}));
    }
    if (equal == std::string::npos) {
      session.declareResultUnit(unit);
    } else {
      session.declareUnit(unit, std::filesystem::absolute(u.substr(equal + 1)));
    }
  }
  return commandFiles;
}

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
    session.collectErrorsIn(sink); // every command's errors, in one pass
    const std::vector<std::string> commandFiles = declareUnits(args, session);
    InterpreterOptions budget;
    if (args.maxOperations > 0) {
      budget.operationBudget = args.maxOperations;
    }
    budget.memoryBudget = args.maxMemoryMiB << 20;
    Interpreter interpreter(session, sink, budget);
    for (const auto& name : catalog.commandNames()) {
      interpreter.defineCommand(name);
    }
    RunStatus status = RunStatus::Completed;
    for (const std::string& comm : commandFiles) {
      status = interpreter.run(SourceFile::load(comm));
      if (status == RunStatus::Failed || status == RunStatus::SyntaxError || session.finished()) {
        break;
      }
    }
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
