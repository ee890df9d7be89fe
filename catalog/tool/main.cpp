// stella-catalog: developer tool for the keyword catalogue, usable before and besides the
// `stella` executable: `check` (load-time checks), `describe NAME`, `json`, `docs DIR`
// (regenerate doc/catalog), `validate FILE.comm...` (check every call of command files against
// the catalogue, without running operators), `tree FILE.comm...` (the same, printing every
// validated keyword tree with its defaults), `coverage FILE.comm...` (keywords and values no
// file uses).
#include "catalog/Catalog.hpp"

#include "interpreter/Interpreter.hpp"
#include "messages/Messages.hpp"

#include <iostream>

namespace {

// Validates every command call of a file against the catalogue without running operators.
class ValidatingHandler : public stella::CommandHandler {
public:
  bool printTrees = false;
  stella::Value callCommand(const std::string& command, const stella::CallArguments& args,
                            const std::string& target) override {
    stella::ValidatedCall v = stella::Catalog::builtin().validate(command, args);
    if (printTrees) {
      std::cout << (target.empty() ? "" : target + " = ") << command << "(\n"
                << v.keywords.format(4) << ")\n";
    }
    finished_ = finished_ || command == "FIN";
    if (v.reused) {
      return stella::Value(v.reused);
    }
    if (v.resultType.empty()) {
      return stella::Value();
    }
    auto c = std::make_shared<stella::Concept>();
    c->name = target;
    c->type = v.resultType;
    return stella::Value(c);
  }
  stella::Value conceptAttribute(const std::shared_ptr<stella::Concept>& c, const std::string& name,
                                 const stella::SourceLocation& at) override {
    throw stella::UserError(stella::msg::make("CATALOG_CHECK", {{"name", c->name}, {"name_2", name}}, at));
  }
  bool finished() const override { return finished_; }

private:
  bool finished_ = false;
};

class PrintingSink : public stella::DiagnosticSink {
public:
  int errors = 0;
  void report(const stella::Diagnostic& d) override {
    errors += d.severity == stella::Severity::Fatal ? 1 : 0;
    std::cerr << stella::formatDiagnostic(d) << "\n";
  }
};

int validateFiles(const std::vector<std::string>& files, bool printTrees) {
  int failed = 0;
  for (const auto& f : files) {
    ValidatingHandler handler;
    handler.printTrees = printTrees;
    PrintingSink sink;
    stella::Interpreter interp(handler, sink);
    for (const auto& name : stella::Catalog::builtin().commandNames()) {
      interp.defineCommand(name);
    }
    stella::RunStatus status = interp.run(stella::SourceFile::load(f));
    bool ok = status == stella::RunStatus::Completed || status == stella::RunStatus::Finished;
    std::cout << f << ": " << (ok ? "valid" : "INVALID") << "\n";
    failed += ok ? 0 : 1;
  }
  return failed == 0 ? 0 : 1;
}

int usage() {
  std::cerr << "usage: stella-catalog check | list | describe NAME | json | docs DIR | validate FILE.comm... "
               "| coverage FILE.comm...\n";
  return 2;
}

int run(const std::vector<std::string>& args) {
  using stella::Catalog;
  if (args.empty()) {
    return usage();
  }
  const std::string& what = args[0];
  if (what == "check") {
    Catalog::builtin(); // throws InternalError listing every problem
    std::cout << "catalogue OK: " << Catalog::builtin().commandNames().size() << " commands\n";
    return 0;
  }
  if (what == "list") {
    for (const auto& n : Catalog::builtin().commandNames()) {
      std::cout << n << "\n";
    }
    return 0;
  }
  if (what == "describe" && args.size() == 2) {
    std::cout << Catalog::builtin().describe(args[1]);
    return 0;
  }
  if (what == "json") {
    std::cout << Catalog::builtin().toJson();
    return 0;
  }
  if (what == "docs" && args.size() == 2) {
    stella::writeCatalogDocs(args[1]);
    return 0;
  }
  if (what == "validate" && args.size() > 1) {
    return validateFiles(std::vector<std::string>(args.begin() + 1, args.end()), false);
  }
  if (what == "tree" && args.size() > 1) {
    return validateFiles(std::vector<std::string>(args.begin() + 1, args.end()), true);
  }
  if (what == "coverage") {
    std::vector<std::filesystem::path> files(args.begin() + 1, args.end());
    std::cout << stella::catalogCoverage(files);
    return 0;
  }
  return usage();
}

} // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const stella::UserError& e) {
    for (const auto& d : e.diagnostics()) {
      std::cerr << stella::formatDiagnostic(d) << "\n";
    }
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return 3;
  }
}
