// The catalogue and the operator registry agree (issue 15): every command of the catalogue has an
// operator unless its entry is marked non_implemente=, a command so marked has none, and every
// operator has a catalogue entry.
#include "catalog/Catalog.hpp"
#include "catalog/CommandSpec.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(CatalogRegistry, EveryCommandHasAnOperatorOrIsMarkedNotImplemented) {
  const Catalog& catalog = Catalog::builtin();
  int marked = 0;
  for (const std::string& name : catalog.commandNames()) {
    const CommandSpec* spec = catalog.find(name);
    ASSERT_NE(spec, nullptr) << name;
    const bool hasOperator = OperatorRegistry::instance().find(name) != nullptr;
    if (spec->notImplemented) {
      ++marked;
      EXPECT_FALSE(hasOperator) << name << " has an operator: remove non_implemente= from " << spec->file;
    } else {
      EXPECT_TRUE(hasOperator) << name << " has no operator: mark it non_implemente='...' in " << spec->file;
    }
  }
  EXPECT_GE(marked, 1); // DYNA_NON_LINE
}

TEST(CatalogRegistry, EveryOperatorHasACatalogueEntry) {
  const std::vector<std::string> names = OperatorRegistry::instance().names();
  EXPECT_GT(names.size(), 30u);
  for (const std::string& name : names) {
    EXPECT_NE(Catalog::builtin().find(name), nullptr) << "the operator " << name << " has no catalogue entry";
  }
}

} // namespace
} // namespace stella
