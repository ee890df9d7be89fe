// Every keyword of STAT_NON_LINE's catalogue is classified (implemented, accepted without effect,
// or refused), and every refused one is refused by name when a user gives it.

#include "solver/nonlinear/StatNonLineKeywords.hpp"
#include "catalog/Catalog.hpp"
#include "catalog/CommandSpec.hpp"
#include "interpreter/Diagnostics.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

void collect(const Level& level, const std::string& prefix, std::vector<std::string>& paths) {
  for (const Entry& e : level.entries) {
    if (e.block) {
      collect(e.block->body, prefix, paths); // blocks are transparent
    } else if (e.factor) {
      paths.push_back(prefix + e.name);
      collect(e.factor->body, prefix + e.name + "/", paths);
    } else if (e.simple && e.simple->renamedTo.empty()) {
      paths.push_back(prefix + e.name);
    }
  }
}

std::vector<std::string> catalogPaths() {
  const CommandSpec* spec = Catalog::builtin().find("STAT_NON_LINE");
  EXPECT_NE(spec, nullptr);
  std::vector<std::string> paths;
  if (spec != nullptr) {
    collect(spec->body, "", paths);
  }
  return paths;
}

TEST(StatNonLineKeywords, EveryCatalogueKeywordIsClassified) {
  const auto paths = catalogPaths();
  EXPECT_GT(paths.size(), 100u);
  for (const auto& p : paths) {
    EXPECT_NE(statNonLineKeywordStatus(p), nullptr) << p << " is neither implemented nor refused";
  }
}

TEST(StatNonLineKeywords, TableNamesOnlyCatalogueKeywords) {
  const auto paths = catalogPaths();
  for (const auto& [path, status] : statNonLineKeywords()) {
    EXPECT_NE(std::find(paths.begin(), paths.end(), path), paths.end()) << path << " is not in the catalogue";
  }
}

// A tree holding only `path` (A/B: factor A with one occurrence holding B) given by the user.
KeywordTree treeWith(const std::string& path) {
  KeywordTree top;
  const auto slash = path.find('/');
  if (slash == std::string::npos) {
    SimpleKeyword k;
    k.name = path;
    k.values = {Value("NOT_A_DEFAULT")};
    top.addSimple(k);
    return top;
  }
  FactorKeyword f;
  f.name = path.substr(0, slash);
  f.occurrences.push_back(treeWith(path.substr(slash + 1)));
  top.addFactor(f);
  return top;
}

TEST(StatNonLineKeywords, RefusedKeywordsAreRefusedByName) {
  int refused = 0;
  for (const auto& p : catalogPaths()) {
    const KeywordStatus* s = statNonLineKeywordStatus(p);
    if (s == nullptr || s->support != KeywordSupport::Refused) {
      continue;
    }
    ++refused;
    try {
      refuseUnsupportedKeywords(treeWith(p));
      ADD_FAILURE() << p << " was accepted";
    } catch (const UserError& e) {
      EXPECT_EQ(e.first().id, "SNL_1") << p;
      // The message names the keyword or the refused factor holding it.
      const std::string head = p.substr(0, p.find('/'));
      EXPECT_NE(e.first().message.find(head), std::string::npos) << e.first().message;
      EXPECT_NE(e.first().message.find("not implemented yet"), std::string::npos);
    }
  }
  EXPECT_GT(refused, 30);
}

TEST(StatNonLineKeywords, ImplementedAndDefaultedKeywordsPass) {
  EXPECT_NO_THROW(refuseUnsupportedKeywords(treeWith("NEWTON/REAC_INCR")));
  EXPECT_NO_THROW(refuseUnsupportedKeywords(treeWith("ARCHIVAGE/PAS_ARCH")));
  // A refused keyword given with its default value is accepted (CONVERGENCE ARRET='OUI').
  KeywordTree top;
  FactorKeyword f;
  f.name = "CONVERGENCE";
  KeywordTree occ;
  SimpleKeyword k;
  k.name = "ARRET";
  k.values = {Value("OUI")};
  occ.addSimple(k);
  f.occurrences.push_back(occ);
  top.addFactor(f);
  EXPECT_NO_THROW(refuseUnsupportedKeywords(top));
}

} // namespace
} // namespace stella
