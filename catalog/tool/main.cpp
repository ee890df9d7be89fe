// stella-catalog: developer tool for the keyword catalogue, usable before and besides the
// `stella` executable: `check` (load-time checks), `describe NAME`, `json`, `docs DIR`
// (regenerate doc/catalog), `coverage FILE.comm...` (keywords and values no file uses).
#include "catalog/Catalog.hpp"

#include <iostream>

namespace {

int usage() {
  std::cerr
      << "usage: stella-catalog check | list | describe NAME | json | docs DIR | coverage FILE.comm...\n";
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
