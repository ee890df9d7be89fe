#pragma once
// Helpers for the mesh file tests: a "zoo" mesh holding one cell of every type, the volume cells
// of a structured box, a temporary directory, and a field-by-field mesh comparison.

#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/Mesh.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace stella::testing {

inline std::filesystem::path tempDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("stella_" + name + "_" + std::to_string(static_cast<long>(::getpid())));
  std::filesystem::create_directories(dir);
  return dir;
}

// The volume cells of a structured box without its skin cells (meshio wants every field to cover
// every cell type of the mesh), with the box's node groups when `withNodeGroups`.
inline Mesh structuredVolume(const StructuredSpec& spec, bool withNodeGroups = true) {
  const Mesh full = buildStructuredMesh(spec);
  Mesh m;
  for (NodeId n = 0; n < full.nodeCount(); ++n) {
    m.addNode(full.point(n));
  }
  for (const CellId c : *full.cellGroup("VOLUME")) {
    m.addCell(full.cellType(c), full.cellNodes(c));
  }
  if (withNodeGroups) {
    for (const auto& [name, nodes] : full.nodeGroups()) {
      m.setNodeGroup(name, nodes);
    }
  }
  return m;
}

// One cell of every type in `types`, each on its own nodes, shifted along x; groups: VOLUMES
// (3D cells), OTHERS (the rest), ALL (every cell, overlapping the two), node group FIRST (the
// nodes of the first cell).
inline Mesh zooMesh(const std::vector<CellType>& types) {
  Mesh m;
  std::vector<CellId> volumes;
  std::vector<CellId> others;
  std::vector<CellId> all;
  double shift = 0.0;
  for (const CellType t : types) {
    std::vector<NodeId> nodes;
    for (const auto& x : referenceCoordinates(t)) {
      nodes.push_back(m.addNode({x[0] + shift, x[1] + 0.5 * x[0] * x[1], x[2] + 0.1 * x[0]}));
    }
    const CellId c = m.addCell(t, nodes);
    (dimension(t) == 3 ? volumes : others).push_back(c);
    all.push_back(c);
    shift += 3.0;
  }
  m.setCellGroup("VOLUMES", volumes);
  m.setCellGroup("OTHERS", others);
  m.setCellGroup("ALL", all);
  m.setNodeGroup("FIRST", m.nodesOfCells(std::vector<CellId>{0}));
  return m;
}

inline void expectSameMesh(const Mesh& a, const Mesh& b, bool compareNames = true) {
  ASSERT_EQ(a.nodeCount(), b.nodeCount());
  ASSERT_EQ(a.cellCount(), b.cellCount());
  EXPECT_EQ(a.dimension(), b.dimension());
  for (NodeId n = 0; n < a.nodeCount(); ++n) {
    for (int d = 0; d < 3; ++d) {
      EXPECT_DOUBLE_EQ(a.point(n)[d], b.point(n)[d]) << "node " << n;
    }
    if (compareNames) {
      EXPECT_EQ(a.nodeName(n), b.nodeName(n));
    }
  }
  for (CellId c = 0; c < a.cellCount(); ++c) {
    ASSERT_EQ(a.cellType(c), b.cellType(c)) << "cell " << c;
    const auto na = a.cellNodes(c);
    const auto nb = b.cellNodes(c);
    EXPECT_TRUE(std::equal(na.begin(), na.end(), nb.begin())) << "cell " << c << " " << name(a.cellType(c));
    if (compareNames) {
      EXPECT_EQ(a.cellName(c), b.cellName(c));
    }
  }
  EXPECT_EQ(a.cellGroups(), b.cellGroups());
  EXPECT_EQ(a.nodeGroups(), b.nodeGroups());
}

} // namespace stella::testing
