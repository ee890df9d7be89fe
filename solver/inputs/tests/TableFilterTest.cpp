// FILTRE of IMPR_TABLE and TEST_TABLE on real values, with the keyword trees the catalogue
// validates: PRECISION and CRITERE decide equality where the catalogue gives them (every FILTRE of
// TEST_TABLE, CRIT_COMP='EQ' or 'NE' of IMPR_TABLE), and IMPR_TABLE's LT, GT, LE, GE compare
// exactly, as their block has no PRECISION.

#include "solver/inputs/TableFilter.hpp"
#include "catalog/tests/CatalogRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

// X = 1.0, 1.0005, 2.0: 1.0 is within IMPR_TABLE's default PRECISION (1e-3, relative) of 1.0005.
Table xs() {
  Table t;
  for (const double x : {1.0, 1.0005, 2.0}) {
    t.addRow({{"X", Value(x)}});
  }
  return t;
}

std::vector<KeywordTree> filters(const std::string& command, const std::string& filtre) {
  const std::string extra = command == "TEST_TABLE" ? ", NOM_PARA='X', VALE_CALC=1.0" : "";
  auto r = catalog_test::run("T = CREA_TABLE(LISTE=_F(PARA='X', LISTE_R=(1.0, 1.0005, 2.0)))\n" + command +
                             "(TABLE=T, FILTRE=_F(" + filtre + ")" + extra + ")\n");
  EXPECT_TRUE(catalog_test::valid(*r));
  EXPECT_EQ(r->handler.calls.back().first, command);
  return r->last().keywords.occurrences("FILTRE");
}

using Rows = std::vector<std::size_t>;

TEST(TableFilter, EqualityUsesTheCataloguePrecision) {
  EXPECT_EQ(filterRows(xs(), filters("IMPR_TABLE", "NOM_PARA='X', VALE=1.0005")), (Rows{0, 1}));
  EXPECT_EQ(filterRows(xs(), filters("IMPR_TABLE", "NOM_PARA='X', VALE=1.0005, PRECISION=1e-6")), (Rows{1}));
  EXPECT_EQ(filterRows(xs(), filters("IMPR_TABLE", "NOM_PARA='X', CRIT_COMP='NE', VALE=1.0005")), (Rows{2}));
  EXPECT_EQ(filterRows(xs(), filters("TEST_TABLE", "NOM_PARA='X', VALE=1.0005")), (Rows{0, 1}));
  EXPECT_EQ(
      filterRows(xs(), filters("TEST_TABLE", "NOM_PARA='X', VALE=1.0005, CRITERE='ABSOLU', PRECISION=1e-4")),
      (Rows{1}));
}

TEST(TableFilter, OrderComparisonsOfImprTableAreExact) {
  // No PRECISION in the block of LT, GT, LE, GE of IMPR_TABLE: 1.0 < 1.0005 (the former C++
  // fallback of 1e-3 made them equal, and 1.0 was not kept).
  EXPECT_EQ(filterRows(xs(), filters("IMPR_TABLE", "NOM_PARA='X', CRIT_COMP='LT', VALE=1.0005")), (Rows{0}));
  EXPECT_EQ(filterRows(xs(), filters("IMPR_TABLE", "NOM_PARA='X', CRIT_COMP='GE', VALE=1.0005")),
            (Rows{1, 2}));
  // TEST_TABLE gives PRECISION to every criterion: 1.0 equals 1.0005 there, so it is not LT.
  EXPECT_EQ(filterRows(xs(), filters("TEST_TABLE", "NOM_PARA='X', CRIT_COMP='LT', VALE=1.0005")), (Rows{}));
}

} // namespace
} // namespace stella
