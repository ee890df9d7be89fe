#pragma once
// Test helpers of the contact kernel: two structured blocks in one mesh (groups prefixed with
// the block's name), and keyword trees built by hand as the catalogue's validator would.

#include "catalog/KeywordTree.hpp"
#include "solver/mesh/Mesh.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <string>

namespace stella::contact::testing {

// Appends `part` to `mesh`, prefixing its groups with `prefix` (e.g. "B_YMIN").
inline void appendMesh(Mesh& mesh, const Mesh& part, const std::string& prefix) {
  const NodeId base = mesh.nodeCount();
  const CellId cellBase = mesh.cellCount();
  for (NodeId n = 0; n < part.nodeCount(); ++n) {
    mesh.addNode(part.point(n));
  }
  for (CellId c = 0; c < part.cellCount(); ++c) {
    std::vector<NodeId> nodes(part.cellNodes(c).begin(), part.cellNodes(c).end());
    for (auto& n : nodes) {
      n += base;
    }
    mesh.addCell(part.cellType(c), nodes);
  }
  for (const auto& [name, cells] : part.cellGroups()) {
    std::vector<CellId> shifted = cells;
    for (auto& c : shifted) {
      c += cellBase;
    }
    mesh.setCellGroup(prefix + name, shifted);
  }
  for (const auto& [name, nodes] : part.nodeGroups()) {
    std::vector<NodeId> shifted = nodes;
    for (auto& n : shifted) {
      n += base;
    }
    mesh.setNodeGroup(prefix + name, shifted);
  }
}

// Block A = [0,1]^d below, block B above shifted by `gap` in y (2D) or z (3D).
inline Mesh twoBlocks(CellType type, int na, int nb, double gap) {
  const bool threeD = info(type).dimension == 3;
  StructuredSpec a;
  a.type = type;
  a.divisions = {na, na, na};
  StructuredSpec b = a;
  b.divisions = {nb, nb, nb};
  if (threeD) {
    b.origin = {0.0, 0.0, 1.0 + gap};
  } else {
    b.origin = {0.0, 1.0 + gap, 0.0};
  }
  Mesh mesh;
  mesh.setDimension(threeD ? 3 : 2);
  appendMesh(mesh, buildStructuredMesh(a), "A_");
  appendMesh(mesh, buildStructuredMesh(b), "B_");
  return mesh;
}

// The DDL_IMPO of twoBlocks' symmetry planes (x = 0 of both blocks, y = 0 of A, and in 3D y = 0 of
// both and z = 0 of A), for AFFE_CHAR_MECA(DDL_IMPO=(...)).
inline std::string blockSymmetries(bool threeD) {
  return threeD ? "_F(GROUP_MA=('A_XMIN', 'B_XMIN'), DX=0.0), _F(GROUP_MA=('A_YMIN', 'B_YMIN'), DY=0.0), "
                  "_F(GROUP_MA='A_ZMIN', DZ=0.0)"
                : "_F(GROUP_MA=('A_XMIN', 'B_XMIN'), DX=0.0), _F(GROUP_MA='A_YMIN', DY=0.0)";
}

inline SimpleKeyword simple(const std::string& name, ValueList values) {
  SimpleKeyword k;
  k.name = name;
  k.values = std::move(values);
  return k;
}

} // namespace stella::contact::testing
