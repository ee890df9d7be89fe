// Mesh model: nodes, cells, names (default and stored), groups and the memory budget.

#include "solver/mesh/Mesh.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

Mesh twoQuads() {
  Mesh m;
  m.setDimension(2);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      m.addNode({double(i), double(j), 0.0});
    }
  }
  const NodeId a[] = {0, 1, 4, 3};
  const NodeId b[] = {1, 2, 5, 4};
  m.addCell(CellType::QUAD4, a);
  m.addCell(CellType::QUAD4, b);
  return m;
}

TEST(Mesh, NodesCellsAndDefaultNames) {
  const Mesh m = twoQuads();
  EXPECT_EQ(m.nodeCount(), 6);
  EXPECT_EQ(m.cellCount(), 2);
  EXPECT_EQ(m.cellType(1), CellType::QUAD4);
  EXPECT_EQ(m.cellNodes(1)[2], 5);
  EXPECT_EQ(m.nodeName(5), "N6");
  EXPECT_EQ(m.cellName(0), "M1");
  EXPECT_EQ(m.findNode("N3"), 2);
  EXPECT_FALSE(m.findNode("N7").has_value());
  EXPECT_FALSE(m.findNode("N0").has_value());
  EXPECT_FALSE(m.findNode("N01").has_value());
  EXPECT_FALSE(m.findNode("X1").has_value());
  EXPECT_TRUE(m.nodeNames().isDefault());
  EXPECT_EQ(m.maxCellDimension(), 2);
}

TEST(Mesh, StoredNamesAndLookup) {
  Mesh m;
  m.addNode({0, 0, 0}, "N1");
  EXPECT_TRUE(m.nodeNames().isDefault());
  m.addNode({1, 0, 0}, "TOP");
  m.addNode({2, 0, 0});
  EXPECT_FALSE(m.nodeNames().isDefault());
  EXPECT_EQ(m.nodeName(0), "N1");
  EXPECT_EQ(m.nodeName(1), "TOP");
  EXPECT_EQ(m.nodeName(2), "N3");
  EXPECT_EQ(m.findNode("TOP"), 1);
  EXPECT_EQ(m.findNode("N3"), 2);
  EXPECT_FALSE(m.findNode("N2").has_value());
}

TEST(Mesh, GeneratedNamesStayUnique) {
  NameTable t('N');
  t.append("N2");
  t.appendDefault(1); // would be N2: must not collide
  EXPECT_EQ(t.name(0), "N2");
  EXPECT_NE(t.name(1), "N2");
  EXPECT_EQ(t.find(t.name(1)), 1);
}

TEST(Mesh, GroupsAreSortedAndUnique) {
  Mesh m = twoQuads();
  m.setCellGroup("RIGHT", {1, 1, 0});
  m.setNodeGroup("BOTTOM", {2, 0, 1});
  ASSERT_NE(m.cellGroup("RIGHT"), nullptr);
  EXPECT_EQ(*m.cellGroup("RIGHT"), (std::vector<CellId>{0, 1}));
  EXPECT_EQ(*m.nodeGroup("BOTTOM"), (std::vector<NodeId>{0, 1, 2}));
  const CellId right[] = {1};
  EXPECT_EQ(m.nodesOfCells(right), (std::vector<NodeId>{1, 2, 4, 5}));
  EXPECT_TRUE(m.removeCellGroup("RIGHT"));
  EXPECT_FALSE(m.hasCellGroup("RIGHT"));
}

TEST(Mesh, MemoryBudgetOfAHexMesh) {
  // 30^3 hexahedra: the budget is 100 bytes per node and 200 per linear cell (groups aside).
  const int n = 30;
  Mesh m;
  m.reserveNodes((n + 1) * (n + 1) * (n + 1));
  m.reserveCells(n * n * n, 8 * n * n * n);
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        m.addNode({double(i), double(j), double(k)});
      }
    }
  }
  const auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const NodeId c[] = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        m.addCell(CellType::HEXA8, c);
      }
    }
  }
  const double bytes = static_cast<double>(m.memoryBytes(false));
  EXPECT_LT(bytes, 100.0 * m.nodeCount() + 200.0 * m.cellCount());
}

} // namespace
} // namespace stella
