// IMPR_RESU FORMAT='RESULTAT' with GROUP_NO / GROUP_MA prints the rows of the group's nodes (nodal
// fields) and cells (Gauss-point fields) only, not every node of the mesh; the other formats are
// not restricted yet and say so (alarm IMPR_RESU_4). Cube of testcases/plate_plasticity (HEXA8).

#include "solver/nonlinear/tests/StudyRun.hpp"
#include "solver/post/tests/PulledCube.hpp"

#include <gtest/gtest.h>
#include <set>
#include <sstream>

namespace stella {
namespace {

using testing::kCubeMesh;
using testing::kPulledCube;
using testing::runStudy;

// The first words of the rows of the table of `field` in `resu` (node or cell names).
std::vector<std::string> rowNames(const std::string& resu, const std::string& field) {
  std::vector<std::string> names;
  const auto start = resu.find(" CHAMP " + field + " ");
  if (start == std::string::npos) {
    return names;
  }
  std::istringstream in(resu.substr(start));
  std::string line;
  std::getline(in, line); // title
  std::getline(in, line); // header
  while (std::getline(in, line) && !line.empty()) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    names.push_back(first);
  }
  return names;
}

TEST(ImprResuGroups, ResultatFormatPrintsOnlyTheGroups) {
  const std::string comm =
      kPulledCube + R"(IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=R, NOM_CHAM='DEPL', GROUP_NO='X1'))
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=R, NOM_CHAM='SIEF_ELGA', GROUP_MA='ALL', NOM_CMP='SIXX'))
IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=R, NOM_CHAM='SIEF_ELGA', GROUP_NO='X1', NOM_CMP='SIXX'))
IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=R, NOM_CHAM='DEPL', GROUP_MA='ALL'))
FIN()
)";
  auto run = runStudy("impr_groups", comm, kCubeMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  const auto r = run->result("R");
  const Mesh& mesh = *r->mesh;
  const std::string resu = run->resu.str();
  // DEPL on GROUP_NO X1: exactly its nodes, each once, every value DX = 1e-3.
  std::set<std::string> x1;
  for (NodeId n : *mesh.nodeGroup("X1")) {
    x1.insert(mesh.nodeName(n));
  }
  const auto nodes = rowNames(resu, "DEPL");
  EXPECT_EQ(nodes.size(), x1.size()) << resu.substr(0, 3000);
  EXPECT_EQ(std::set<std::string>(nodes.begin(), nodes.end()), x1);
  EXPECT_LT(x1.size(), static_cast<std::size_t>(mesh.nodeCount()));
  // SIEF_ELGA on GROUP_MA ALL: the 50 HEXA8 x 8 Gauss points, no skin cell.
  const auto points = rowNames(resu, "SIEF_ELGA");
  EXPECT_EQ(points.size(), mesh.cellGroup("ALL")->size() * 8);
  // SIEF_ELGA with GROUP_NO alone: the volume cells touching x = 1 (fewer than all).
  const auto second = resu.find(" CHAMP SIEF_ELGA ", resu.find(" CHAMP SIEF_ELGA ") + 1);
  ASSERT_NE(second, std::string::npos);
  const auto touching = rowNames(resu.substr(second), "SIEF_ELGA");
  EXPECT_GT(touching.size(), 0u);
  EXPECT_LT(touching.size(), points.size());
  EXPECT_EQ(touching.size() % 8, 0u);
  EXPECT_NE(run->mess().find("IMPR_RESU_4"), std::string::npos);
}

} // namespace
} // namespace stella
