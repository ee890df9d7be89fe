// Checks the reference topology tables geometrically: mid-edge nodes lie at the middle of their
// edge, faces point out of the cell, face mid nodes belong to the face's edges, volume cells are
// positively oriented.

#include "solver/mesh/CellTopology.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella {
namespace {

using V = std::array<double, 3>;

V sub(const V& a, const V& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V cross(const V& a, const V& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const V& a, const V& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

V centroid(const std::vector<V>& x, const std::vector<int>& ids) {
  V c{0, 0, 0};
  for (int i : ids) {
    for (int d = 0; d < 3; ++d) {
      c[d] += x[i][d] / static_cast<double>(ids.size());
    }
  }
  return c;
}

TEST(CellTopology, MidNodesAreAtEdgeMiddles) {
  for (const auto& info : cellTypeTable) {
    const auto x = referenceCoordinates(info.type);
    ASSERT_EQ(static_cast<int>(x.size()), info.nodeCount) << info.name;
    for (const auto& e : cellEdges(info.type)) {
      if (e.mid < 0) {
        continue;
      }
      for (int d = 0; d < 3; ++d) {
        EXPECT_DOUBLE_EQ(x[e.mid][d], 0.5 * (x[e.a][d] + x[e.b][d])) << info.name;
      }
    }
  }
}

TEST(CellTopology, EveryNodeOfAQuadraticCellIsReached) {
  // Each non-vertex node is a mid-edge node or a face centre (or the cell centre).
  for (const auto& info : cellTypeTable) {
    if (info.dimension < 3 || !info.quadratic) {
      continue;
    }
    std::vector<int> seen(static_cast<std::size_t>(info.nodeCount), 0);
    for (const auto& f : cellFaces(info.type)) {
      for (int n : f.nodes) {
        seen[static_cast<std::size_t>(n)] = 1;
      }
    }
    int missing = 0;
    for (int s : seen) {
      missing += s == 0 ? 1 : 0;
    }
    EXPECT_EQ(missing, info.type == CellType::HEXA27 ? 1 : 0) << info.name;
  }
}

TEST(CellTopology, FacesPointOutward) {
  for (const auto& info : cellTypeTable) {
    if (info.dimension != 3) {
      continue;
    }
    const auto x = referenceCoordinates(info.type);
    std::vector<int> vertices;
    for (int i = 0; i < vertexCount(info.type); ++i) {
      vertices.push_back(i);
    }
    const V c = centroid(x, vertices);
    const auto faces = cellFaces(info.type);
    int total = 0;
    for (const auto& f : faces) {
      const int nv = vertexCount(f.type);
      ASSERT_EQ(static_cast<int>(f.nodes.size()), nodeCount(f.type)) << info.name;
      const V n = cross(sub(x[f.nodes[1]], x[f.nodes[0]]), sub(x[f.nodes[nv - 1]], x[f.nodes[0]]));
      std::vector<int> fv(f.nodes.begin(), f.nodes.begin() + nv);
      EXPECT_GT(dot(n, sub(centroid(x, fv), c)), 0.0) << info.name;
      // Face mid nodes are the middles of consecutive face vertices.
      for (int i = nv; i < 2 * nv && i < static_cast<int>(f.nodes.size()); ++i) {
        const V& a = x[f.nodes[i - nv]];
        const V& b = x[f.nodes[(i - nv + 1) % nv]];
        for (int d = 0; d < 3; ++d) {
          EXPECT_DOUBLE_EQ(x[f.nodes[i]][d], 0.5 * (a[d] + b[d])) << info.name;
        }
      }
      total += 1;
    }
    const int expected = shapeOf(info.type) == CellShape::Tetrahedron  ? 4
                         : shapeOf(info.type) == CellShape::Hexahedron ? 6
                                                                       : 5;
    EXPECT_EQ(total, expected) << info.name;
  }
}

TEST(CellTopology, VolumeCellsArePositive) {
  for (const auto& info : cellTypeTable) {
    if (info.dimension != 3) {
      continue;
    }
    const auto x = referenceCoordinates(info.type);
    // Corner 0 with its three (or for the pyramid apex, two base) neighbours.
    const V e1 = sub(x[1], x[0]);
    const int third = shapeOf(info.type) == CellShape::Tetrahedron   ? 2
                      : shapeOf(info.type) == CellShape::Pentahedron ? 2
                                                                     : 3;
    const int up = shapeOf(info.type) == CellShape::Tetrahedron   ? 3
                   : shapeOf(info.type) == CellShape::Pentahedron ? 3
                   : shapeOf(info.type) == CellShape::Pyramid     ? 4
                                                                  : 4;
    EXPECT_GT(dot(cross(e1, sub(x[third], x[0])), sub(x[up], x[0])), 0.0) << info.name;
  }
}

TEST(CellTopology, LinearAndQuadraticCounterparts) {
  EXPECT_EQ(linearType(CellType::HEXA27), CellType::HEXA8);
  EXPECT_EQ(quadraticType(CellType::PENTA6), CellType::PENTA15);
  EXPECT_EQ(vertexCount(CellType::PYRAM13), 5);
  EXPECT_EQ(cellFaces(CellType::QUAD8).size(), 4u);
  EXPECT_EQ(cellFaces(CellType::QUAD8)[1].nodes, (std::vector<int>{1, 2, 5}));
  EXPECT_EQ(cellFaces(CellType::HEXA27)[0].nodes, (std::vector<int>{0, 3, 2, 1, 11, 10, 9, 8, 20}));
}

} // namespace
} // namespace stella
