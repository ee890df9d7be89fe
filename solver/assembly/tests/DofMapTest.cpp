// The run's numbering of the unknowns (DofMap): DX, DY, DZ node by node for the nodes that carry
// cells of the model, nothing for the others, then one Lagrange multiplier per relation; every
// equation described in words (node name and component, or the relation of a multiplier).

#include "solver/assembly/tests/ElasticStudy.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(DofMap, NumbersActiveNodesThenMultipliersAndDescribesThem) {
  // nodes N1..N10 of a HEXA8 and two nodes outside it: N2 and N10 carry no DOF
  auto mesh = std::make_shared<Mesh>();
  mesh->setDimension(3);
  const Point3 points[] = {{0, 0, 0}, {5, 5, 5}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {6, 6, 6}};
  for (const Point3& x : points) {
    mesh->addNode(x);
  }
  const NodeId hexa[] = {0, 2, 3, 4, 5, 6, 7, 8};
  mesh->addCell(CellType::HEXA8, hexa);
  auto model = testing::modelOn(mesh, "3D");
  DofMap dofs(*model);
  EXPECT_EQ(dofs.components(), 3);
  EXPECT_EQ(dofs.physicalCount(), 24);
  EXPECT_EQ(dofs.dof(1, 0), -1);
  EXPECT_EQ(dofs.dof(9, 2), -1);
  EXPECT_EQ(dofs.dof(2, 1), 4);
  EXPECT_EQ(dofs.node(4), 2);
  EXPECT_EQ(dofs.component(4), 1);
  EXPECT_EQ(dofs.describe(4, *mesh), "node N3, component DY");
  const std::vector<LinearRelation> relations{{{{2, 1, 1.0}}, 0.0, "DDL_IMPO"},
                                              {{{3, 0, 1.0}, {8, 2, -1.0}}, 0.0, "LIAISON_DDL"}};
  EXPECT_EQ(dofs.addRelations(relations), 24);
  EXPECT_EQ(dofs.size(), 26);
  EXPECT_EQ(dofs.lagrangeCount(), 2);
  EXPECT_EQ(dofs.describe(24, *mesh), "Lagrange multiplier of DDL_IMPO on N3 DY");
  EXPECT_EQ(dofs.describe(25, *mesh), "Lagrange multiplier of LIAISON_DDL on N4 DX + N9 DZ");
}

} // namespace
} // namespace stella
