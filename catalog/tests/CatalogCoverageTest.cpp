// Tests of the catalogue coverage report (`tools/catalog-coverage`, catalogCoverage()).
#include "catalog/Catalog.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace stella {
namespace {

// A list that contains itself (`a[0] = a`) used to recurse without end in the coverage walk
// (a stack overflow found by hand); it is now walked once and its values still count.
TEST(CatalogCoverage, SelfContainingListIsWalkedOnce) {
  const auto file = std::filesystem::temp_directory_path() / "stella_coverage_selfref.comm";
  {
    std::ofstream out(file);
    out << "DEBUT()\na = ['ANALYTIQUE', 2]\na[1] = a\nTEST_TABLE(REFERENCE=a)\nFIN()\n";
  }
  const std::string report = catalogCoverage({file});
  std::filesystem::remove(file);
  // TEST_TABLE: one keyword (REFERENCE) and one of its values (ANALYTIQUE) used, once.
  EXPECT_NE(report.find("| TEST_TABLE | 27/28 | 25/26 |"), std::string::npos) << report;
}

} // namespace
} // namespace stella
