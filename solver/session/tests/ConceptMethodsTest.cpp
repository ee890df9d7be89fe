// Methods of concepts called from command files, on a mesh made by hand
// (tests/data/two_quads.msh: QUAD4 cells 1 x 0.5 (GAUCHE) and 2 x 0.5 (DROITE) side by side,
// bottom edges BAS (lengths 1 and 2), top edges HAUT; the Gmsh reader makes a node group of
// each physical group): counts, group names, coordinates and
// code_aster's getMinMaxEdgeSizes, whose values follow from the construction.

#include "solver/nonlinear/tests/StudyRun.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::runStudy;

const char* const kMesh = "solver/session/tests/data/two_quads.msh";

TEST(ConceptMethods, MeshCountsGroupsCoordinatesAndEdges) {
  const std::string comm = R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
assert M.getNumberOfNodes() == 6
assert M.getNumberOfCells() == 6
assert M.getGroupsOfCells() == ['BAS', 'DROITE', 'GAUCHE', 'HAUT'], M.getGroupsOfCells()
assert M.getGroupsOfNodes(local=False) == M.getGroupsOfCells(), M.getGroupsOfNodes()
coords = M.getCoordinates()
values = coords.getValues()
assert len(coords) == 18 and len(values) == 18
assert values[6:9] == [3.0, 0.0, 0.0] and coords[-2] == 0.5 and coords[-1] == 0.0
assert [x for x in coords][3] == 1.0
assert M.getMinMaxEdgeSizes('GAUCHE') == (0.5, 1.0)
assert M.getMinMaxEdgeSizes('DROITE') == (0.5, 2.0)
assert M.getMinMaxEdgeSizes('BAS') == (1.0, 2.0)
assert M.getName() == 'M'
try:
    M.getNumberOfNode()
except AttributeError as e:
    print('caught:', e)
FIN()
)";
  auto run = runStudy("concept_methods", comm, kMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  EXPECT_EQ(run->status, RunStatus::Finished) << run->mess();
  EXPECT_NE(run->mess().find("caught: the concept M (maillage) has no attribute 'getNumberOfNode'"),
            std::string::npos)
      << run->mess();
}

TEST(ConceptMethods, UnknownGroupAndMethodAreLocatedErrors) {
  auto unknownGroup = runStudy("concept_methods_group", R"(
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
e = M.getMinMaxEdgeSizes('GAUCH')
)",
                               kMesh);
  EXPECT_EQ(unknownGroup->failure(), FailureKind::Error);
  const std::string mess = unknownGroup->mess();
  EXPECT_NE(mess.find("the mesh M has no cell group (GROUP_MA) 'GAUCH'"), std::string::npos) << mess;
  EXPECT_NE(mess.find("did you mean 'GAUCHE'?"), std::string::npos) << mess;
  EXPECT_NE(mess.find("concept_methods_group.comm:3"), std::string::npos) << mess;

  auto unknownMethod = runStudy("concept_methods_name", R"(
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
n = M.getNumberOfNode()
)",
                                kMesh);
  const std::string mess2 = unknownMethod->mess();
  EXPECT_NE(mess2.find("CONCEPT_1"), std::string::npos) << mess2;
  EXPECT_NE(mess2.find("did you mean 'getNumberOfNodes'?"), std::string::npos) << mess2;
  EXPECT_NE(mess2.find("getMinMaxEdgeSizes"), std::string::npos) << mess2;
}

} // namespace
} // namespace stella
