// `stella catalog`: a command's keyword tree, the list of commands, or the JSON export.

#include "Commands.hpp"
#include "catalog/Catalog.hpp"
#include "interpreter/Suggest.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <iostream>

namespace stella::cli {

int catalog(const CatalogArguments& args) {
  const Catalog& cat = Catalog::builtin();
  if (args.json) {
    std::cout << cat.toJson() << "\n";
    return 0;
  }
  if (args.list || args.command.empty()) {
    for (const auto& name : cat.commandNames()) {
      bool implemented = OperatorRegistry::instance().find(name) != nullptr;
      std::cout << name << (implemented ? "" : "   (not implemented yet)") << "\n";
    }
    return 0;
  }
  if (cat.find(args.command) == nullptr) {
    std::cerr << "stella: the catalogue has no command '" << args.command << "'\n";
    const std::string near = nearestName(args.command, cat.commandNames());
    if (!near.empty()) {
      std::cerr << "       did you mean " << near << "? (`stella catalog " << near << "`)\n";
    }
    std::cerr << "       `stella catalog --list` lists the commands\n";
    return exitUsage;
  }
  std::cout << cat.describe(args.command);
  return 0;
}

} // namespace stella::cli
