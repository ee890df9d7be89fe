// CREA_MAILLAGE/DECOUPE_LAC: for every cell type and both DECOUPE_HEXA, the cut mesh has the
// same volume (isoparametric, Gauss, 1e-12), a positive jacobian at every Gauss point of every
// cell, passes VERI_MAIL, is conforming (every face of a volume cell is shared by two cells or is
// a boundary face; the boundary is the original one, the slave faces replaced by their pieces),
// carries the groups over; the numbers of new nodes and cells are code_aster's.

#include "solver/mesh/LacCutting.hpp"
#include "solver/fem/Quadrature.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshCheck.hpp"
#include "solver/mesh/MeshConversion.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace stella {
namespace {

using Key = std::vector<NodeId>;

// Measure (isoparametric, Gauss) and smallest jacobian of the cells of dimension `dim`.
std::pair<double, double> measureAndMinJacobian(const Mesh& m, int dim) {
  double total = 0;
  double minJ = 1e300;
  for (CellId c = 0; c < m.cellCount(); ++c) {
    const CellType t = m.cellType(c);
    if (dimension(t) != dim) {
      continue;
    }
    const auto& ref = fem::referenceElement(t);
    const auto& rule = fem::rigiRule(t, fem::IntegrationRole::Volume);
    const auto nodes = m.cellNodes(c);
    for (int g = 0; g < rule.size(); ++g) {
      const Eigen::MatrixXd grad = ref.gradients(rule.points[static_cast<std::size_t>(g)]);
      Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(dim, dim);
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Point3 x = m.point(nodes[i]);
        for (int a = 0; a < dim; ++a) {
          for (int b = 0; b < dim; ++b) {
            jac(a, b) += x[static_cast<std::size_t>(a)] * grad(static_cast<Eigen::Index>(i), b);
          }
        }
      }
      const double det = jac.determinant();
      minJ = std::min(minJ, det);
      total += rule.weights[static_cast<std::size_t>(g)] * det;
    }
  }
  return {total, minJ};
}

Key faceKey(const Mesh& m, CellId c, const CellFace& f) {
  Key k;
  for (const int i : f.nodes) {
    k.push_back(m.cellNodes(c)[static_cast<std::size_t>(i)]);
  }
  std::sort(k.begin(), k.end());
  return k;
}

// Faces of the cells of dimension `dim` (full node sets) and how many cells have each.
std::map<Key, int> faceUse(const Mesh& m, int dim) {
  std::map<Key, int> use;
  for (CellId c = 0; c < m.cellCount(); ++c) {
    if (dimension(m.cellType(c)) == dim) {
      for (const auto& f : cellFaces(m.cellType(c))) {
        ++use[faceKey(m, c, f)];
      }
    }
  }
  return use;
}

Key cellKey(const Mesh& m, CellId c) {
  Key k(m.cellNodes(c).begin(), m.cellNodes(c).end());
  std::sort(k.begin(), k.end());
  return k;
}

// Adds the boundary faces of the volume cells as the group SKIN (outward).
void addSkin(Mesh& m) {
  const int dim = m.maxCellDimension();
  const auto use = faceUse(m, dim);
  std::vector<CellId> skin;
  const CellId n = m.cellCount();
  for (CellId c = 0; c < n; ++c) {
    if (dimension(m.cellType(c)) != dim) {
      continue;
    }
    for (const auto& f : cellFaces(m.cellType(c))) {
      if (use.at(faceKey(m, c, f)) == 1) {
        std::vector<NodeId> nodes;
        for (const int i : f.nodes) {
          nodes.push_back(m.cellNodes(c)[static_cast<std::size_t>(i)]);
        }
        skin.push_back(m.addCell(f.type, nodes));
      }
    }
  }
  m.setCellGroup("SKIN", skin);
  m.setNodeGroup("SKIN", m.nodesOfCells(skin));
}

// A box of HEXA8 whose second cell is cut into six pyramids from its centre and the third into
// five pyramids and two tetrahedra (the pyramid on the box's end split along a diagonal).
Mesh mixedMesh() {
  const Mesh h = buildStructuredMesh({CellType::HEXA8, {3, 1, 1}, {3, 1, 1}, {0, 0, 0}});
  Mesh m;
  for (NodeId i = 0; i < h.nodeCount(); ++i) {
    m.addNode(h.point(i));
  }
  std::vector<CellId> body;
  for (const CellId c : *h.cellGroup("VOLUME")) {
    const auto nodes = h.cellNodes(c);
    if (c == 0) {
      body.push_back(m.addCell(CellType::HEXA8, nodes));
      continue;
    }
    const NodeId centre = m.addNode(cellCentroid(h, c));
    for (const auto& f : cellFaces(CellType::HEXA8)) {
      const NodeId b[4] = {
          nodes[static_cast<std::size_t>(f.nodes[0])], nodes[static_cast<std::size_t>(f.nodes[3])],
          nodes[static_cast<std::size_t>(f.nodes[2])], nodes[static_cast<std::size_t>(f.nodes[1])]};
      const bool end =
          c == 2 && std::all_of(std::begin(b), std::end(b), [&](NodeId x) { return h.point(x)[0] > 2.5; });
      if (end) {
        body.push_back(m.addCell(CellType::TETRA4, std::vector<NodeId>{b[0], b[1], b[2], centre}));
        body.push_back(m.addCell(CellType::TETRA4, std::vector<NodeId>{b[0], b[2], b[3], centre}));
      } else {
        body.push_back(m.addCell(CellType::PYRAM5, std::vector<NodeId>{b[0], b[1], b[2], b[3], centre}));
      }
    }
  }
  m.setCellGroup("VOLUME", body);
  addSkin(m);
  return m;
}

Mesh singleCell(CellType t) {
  Mesh m;
  const auto ref = referenceCoordinates(t);
  std::vector<NodeId> nodes;
  for (const auto& x : ref) {
    const double z = dimension(t) == 3 ? 0.8 * x[2] + 0.05 * x[0] : 0.0;
    nodes.push_back(m.addNode({x[0] + 0.1 * x[1], x[1], z}));
  }
  m.setDimension(dimension(t));
  m.setCellGroup("VOLUME", {m.addCell(t, nodes)});
  addSkin(m);
  return m;
}

struct Checked {
  Mesh out;
  int slaveCells = 0;
};

// Cuts `m` under `groups` and checks volume, jacobians, VERI_MAIL, conformity, groups.
Checked cutAndCheck(const Mesh& m, const std::vector<std::string>& groups, LacHexaCut mode,
                    const std::string& what) {
  SCOPED_TRACE(what);
  const int dim = m.maxCellDimension();
  Checked r{cutMeshForLac(m, groups, mode, {}), 0};
  const Mesh& out = r.out;
  const auto [v0, j0] = measureAndMinJacobian(m, dim);
  const auto [v1, j1] = measureAndMinJacobian(out, dim);
  EXPECT_NEAR(v1, v0, 1e-12 * v0);
  EXPECT_GT(j1, 0.0);
  EXPECT_TRUE(checkMesh(out).clean());
  // Conformity: no face of three cells, and the boundary is the original one with each slave
  // face replaced by its pieces.
  std::vector<CellId> slaves;
  for (const auto& g : groups) {
    slaves.insert(slaves.end(), m.cellGroup(g)->begin(), m.cellGroup(g)->end());
  }
  std::sort(slaves.begin(), slaves.end());
  slaves.erase(std::unique(slaves.begin(), slaves.end()), slaves.end());
  r.slaveCells = static_cast<int>(slaves.size());
  std::map<Key, int> before;
  for (const auto& [k, n] : faceUse(m, dim)) {
    if (n == 1) {
      before[k] = 1;
    }
  }
  for (const CellId s : slaves) {
    before.erase(cellKey(m, s));
  }
  std::size_t pieces = 0;
  for (const auto& p : out.lacPatches()) {
    for (const CellId c : p.cells) {
      before[cellKey(out, c)] = 1;
      ++pieces;
    }
  }
  std::map<Key, int> after;
  for (const auto& [k, n] : faceUse(out, dim)) {
    EXPECT_LE(n, 2);
    if (n == 1) {
      after[k] = 1;
    }
  }
  EXPECT_EQ(after, before);
  // Groups: the slave groups hold the pieces (same area), the volume group every volume cell,
  // node groups of the slave surface its new nodes.
  EXPECT_EQ(out.lacPatches().size(), slaves.size());
  std::vector<CellId> volumes;
  for (CellId c = 0; c < out.cellCount(); ++c) {
    if (dimension(out.cellType(c)) == dim) {
      volumes.push_back(c);
    }
  }
  const std::string body = out.hasCellGroup("VOLUME") ? "VOLUME" : "SURFACE";
  EXPECT_TRUE(out.hasCellGroup(body));
  if (out.hasCellGroup(body)) {
    EXPECT_EQ(*out.cellGroup(body), volumes);
  }
  for (const auto& g : groups) {
    double a0 = 0;
    double a1 = 0;
    for (const CellId c : *m.cellGroup(g)) {
      a0 += cellMeasure(m, c);
    }
    for (const CellId c : *out.cellGroup(g)) {
      a1 += cellMeasure(out, c);
    }
    EXPECT_NEAR(a1, a0, 1e-12 * a0) << g;
    Key whole = m.hasNodeGroup(g) ? *m.nodeGroup(g) : Key{};
    std::sort(whole.begin(), whole.end());
    if (out.hasNodeGroup(g) && whole == m.nodesOfCells(*m.cellGroup(g))) { // a node group of the whole face
      Key ng = *out.nodeGroup(g);
      std::sort(ng.begin(), ng.end());
      EXPECT_EQ(ng, out.nodesOfCells(*out.cellGroup(g))) << g;
    }
  }
  EXPECT_GE(pieces, slaves.size());
  return r;
}

TEST(LacCutting, EveryStructuredCellTypeWithItsWholeSkinSlave) {
  const CellType types[] = {CellType::TRIA3,  CellType::TRIA6,   CellType::QUAD4,  CellType::QUAD8,
                            CellType::TETRA4, CellType::TETRA10, CellType::HEXA8,  CellType::HEXA20,
                            CellType::HEXA27, CellType::PENTA6,  CellType::PENTA15};
  for (const CellType t : types) {
    for (const auto mode : {LacHexaCut::Pyramids, LacHexaCut::Hexahedra}) {
      Mesh m = buildStructuredMesh({t, {3, 2, 2}, {3, 2, 1}, {0, 0, 0}});
      // A rotation, a shear and a stretch keep the faces planar: the volume stays exact.
      for (NodeId n = 0; n < m.nodeCount(); ++n) {
        const Point3 x = m.point(n);
        m.setPoint(n, {0.8 * x[0] - 0.6 * x[1] + 0.3 * x[2], 0.6 * x[0] + 0.8 * x[1],
                       dimension(t) == 3 ? 1.7 * x[2] : 0.0});
      }
      const bool volume = m.maxCellDimension() == 3;
      const std::vector<std::string> groups =
          volume ? std::vector<std::string>{"XMIN", "XMAX", "YMIN", "YMAX", "ZMIN", "ZMAX"}
                 : std::vector<std::string>{"XMIN", "XMAX", "YMIN", "YMAX"};
      const auto r = cutAndCheck(m, groups, mode,
                                 std::string(name(t)) + (mode == LacHexaCut::Hexahedra ? " HEXA" : " PYRA"));
      const bool kept = t == CellType::TRIA6 || t == CellType::QUAD8 || t == CellType::HEXA27;
      EXPECT_EQ(r.out.cellCount() == m.cellCount(), kept) << name(t);
    }
  }
}

TEST(LacCutting, PyramidsTetrahedraAndHexahedraTogetherLinearAndQuadratic) {
  const Mesh linear = mixedMesh();
  for (const auto mode : {LacHexaCut::Pyramids, LacHexaCut::Hexahedra}) {
    cutAndCheck(linear, {"SKIN"}, mode, "mixed linear");
    const Mesh quadratic = convertCells(linear, CellConversion::LineToQuad, {});
    cutAndCheck(quadratic, {"SKIN"}, mode, "mixed quadratic");
  }
}

TEST(LacCutting, EveryFaceOfOneCellOfEachType) {
  const CellType types[] = {CellType::TRIA3,  CellType::QUAD4,   CellType::TETRA4, CellType::TETRA10,
                            CellType::PENTA6, CellType::PENTA15, CellType::PYRAM5, CellType::PYRAM13,
                            CellType::HEXA8,  CellType::HEXA20};
  for (const CellType t : types) {
    for (const auto mode : {LacHexaCut::Pyramids, LacHexaCut::Hexahedra}) {
      const Mesh m = singleCell(t);
      cutAndCheck(m, {"SKIN"}, mode, std::string("single ") + std::string(name(t)));
    }
  }
}

// Prisms and pyramids as meshers number them: the numbering may start at any vertex (every
// rotation that keeps the orientation); every face of the cell cut, linear and quadratic, both
// DECOUPE_HEXA (which concerns hexahedra only: the same cut).
TEST(LacCutting, PrismsAndPyramidsNumberedFromAnyVertex) {
  const std::vector<std::vector<int>> prism = {
      {0, 1, 2, 3, 4, 5}, {1, 2, 0, 4, 5, 3}, {2, 0, 1, 5, 3, 4}, {5, 4, 3, 2, 1, 0}, {3, 5, 4, 0, 2, 1}};
  const std::vector<std::vector<int>> pyramid = {
      {0, 1, 2, 3, 4}, {1, 2, 3, 0, 4}, {2, 3, 0, 1, 4}, {3, 0, 1, 2, 4}};
  for (const CellType t : {CellType::PENTA6, CellType::PYRAM5}) {
    for (const auto& perm : t == CellType::PENTA6 ? prism : pyramid) {
      const Mesh one = singleCell(t);
      Mesh m;
      for (NodeId n = 0; n < one.nodeCount(); ++n) {
        m.addNode(one.point(n));
      }
      std::vector<NodeId> nodes;
      for (const int i : perm) {
        nodes.push_back(one.cellNodes(0)[static_cast<std::size_t>(i)]);
      }
      m.setCellGroup("VOLUME", {m.addCell(t, nodes)});
      addSkin(m);
      for (const auto mode : {LacHexaCut::Pyramids, LacHexaCut::Hexahedra}) {
        const std::string what = std::string(name(t)) + " from vertex " + std::to_string(perm[0]);
        const auto linear = cutAndCheck(m, {"SKIN"}, mode, what);
        const auto quadratic =
            cutAndCheck(convertCells(m, CellConversion::LineToQuad, {}), {"SKIN"}, mode, what + " quadratic");
        EXPECT_EQ(linear.out.cellCount(), quadratic.out.cellCount()) << what;
      }
    }
  }
}

// code_aster's numbers of new nodes and of cells replacing the cell and its slave face.
TEST(LacCutting, NewNodesAndPiecesAreCodeAsters) {
  struct Case {
    CellType cell;
    CellType face;
    LacHexaCut mode;
    int newNodes;
    int cellPieces;
    int facePieces;
  };
  const Case cases[] = {
      {CellType::TRIA3, CellType::SEG2, LacHexaCut::Pyramids, 1, 2, 2},
      {CellType::QUAD4, CellType::SEG2, LacHexaCut::Pyramids, 4, 4, 3},
      {CellType::TETRA4, CellType::TRIA3, LacHexaCut::Pyramids, 1, 3, 3},
      {CellType::TETRA10, CellType::TRIA6, LacHexaCut::Pyramids, 5, 3, 3},
      {CellType::HEXA8, CellType::QUAD4, LacHexaCut::Hexahedra, 8, 6, 5},
      {CellType::HEXA8, CellType::QUAD4, LacHexaCut::Pyramids, 1, 5, 4},
      {CellType::HEXA20, CellType::QUAD8, LacHexaCut::Hexahedra, 28, 6, 5},
      {CellType::HEXA20, CellType::QUAD8, LacHexaCut::Pyramids, 9, 5, 4},
      {CellType::PENTA6, CellType::TRIA3, LacHexaCut::Pyramids, 1, 4, 3},
      {CellType::PENTA6, CellType::QUAD4, LacHexaCut::Pyramids, 1, 4, 4},
      {CellType::PENTA15, CellType::TRIA6, LacHexaCut::Pyramids, 7, 4, 3},
      {CellType::PENTA15, CellType::QUAD8, LacHexaCut::Pyramids, 7, 4, 4},
      {CellType::PYRAM5, CellType::QUAD4, LacHexaCut::Pyramids, 1, 4, 4},
      {CellType::PYRAM5, CellType::TRIA3, LacHexaCut::Pyramids, 1, 4, 3},
      {CellType::PYRAM13, CellType::QUAD8, LacHexaCut::Pyramids, 6, 4, 4},
      {CellType::PYRAM13, CellType::TRIA6, LacHexaCut::Pyramids, 6, 4, 3},
  };
  for (const auto& k : cases) {
    Mesh m = singleCell(k.cell);
    CellId face = -1;
    for (const CellId c : *m.cellGroup("SKIN")) {
      if (m.cellType(c) == k.face && face < 0) {
        face = c;
      }
    }
    ASSERT_GE(face, 0) << name(k.cell);
    m.setCellGroup("ESCL", {face});
    const Mesh out = cutMeshForLac(m, {"ESCL"}, k.mode, {});
    EXPECT_EQ(out.nodeCount() - m.nodeCount(), k.newNodes) << name(k.cell) << " " << name(k.face);
    EXPECT_EQ(out.cellGroup("VOLUME")->size(), static_cast<std::size_t>(k.cellPieces)) << name(k.cell);
    EXPECT_EQ(out.cellGroup("ESCL")->size(), static_cast<std::size_t>(k.facePieces)) << name(k.cell);
    cutAndCheck(m, {"ESCL"}, k.mode, std::string("one face of ") + std::string(name(k.cell)));
  }
}

TEST(LacCutting, TetrahedraOfAnyShapeKeepTheirVolume) {
  Mesh m = buildStructuredMesh({CellType::TETRA4, {4, 3, 2}, {2, 1.5, 1}, {0, 0, 0}});
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> d(-0.08, 0.08);
  for (NodeId n = 0; n < m.nodeCount(); ++n) {
    const Point3 x = m.point(n);
    m.setPoint(n, {x[0] + d(gen), x[1] + d(gen), x[2] + d(gen)});
  }
  cutAndCheck(m, {"ZMAX", "XMIN"}, LacHexaCut::Pyramids, "perturbed tetrahedra");
}

// A hexahedron with every face warped (a general trilinear cell), cut under all its faces: the
// pieces fill it exactly (measured: within 1e-15) in both modes.
TEST(LacCutting, WarpedHexahedronKeepsItsVolume) {
  Mesh m;
  const Point3 p[8] = {{0, 0, 0},       {1, 0, 0},       {1, 1, 0},       {0, 1, 0},
                       {0.1, -0.05, 1}, {1.2, 0.1, 1.0}, {0.9, 1.1, 1.3}, {-0.1, 0.8, 1.05}};
  std::vector<NodeId> n;
  for (const auto& x : p) {
    n.push_back(m.addNode(x));
  }
  m.setCellGroup("VOLUME", {m.addCell(CellType::HEXA8, n)});
  addSkin(m);
  for (const Mesh& cell : {m, convertCells(m, CellConversion::LineToQuad, {})}) {
    for (const auto mode : {LacHexaCut::Pyramids, LacHexaCut::Hexahedra}) {
      const Mesh out = cutMeshForLac(cell, {"SKIN"}, mode, {});
      const auto [v0, j0] = measureAndMinJacobian(cell, 3);
      const auto [v1, j1] = measureAndMinJacobian(out, 3);
      EXPECT_NEAR(v1, v0, 1e-12 * v0) << name(cell.cellType(0));
      EXPECT_GT(j1, 0.0);
      EXPECT_TRUE(checkMesh(out).clean());
    }
  }
}

TEST(LacCutting, PatchesFollowTheSlaveGroups) {
  const Mesh m = buildStructuredMesh({CellType::QUAD4, {4, 2, 1}, {2, 1, 1}, {0, 0, 0}});
  const Mesh out = cutMeshForLac(m, {"YMAX", "XMIN"}, LacHexaCut::Pyramids, {});
  ASSERT_EQ(out.lacPatches().size(), 6u);
  EXPECT_EQ(out.lacPatches()[0].zone, "YMAX");
  EXPECT_EQ(out.lacPatches()[5].zone, "XMIN");
  for (const auto& p : out.lacPatches()) {
    EXPECT_EQ(p.cells.size(), 3u);
  }
  // Uncut cells keep their names (the cell (1, 0) is under neither group); pieces are named
  // after the original cells.
  const auto kept = out.findCell(m.cellName(1));
  ASSERT_TRUE(kept.has_value());
  EXPECT_TRUE(std::equal(out.cellNodes(*kept).begin(), out.cellNodes(*kept).end(), m.cellNodes(1).begin()));
  EXPECT_FALSE(out.findCell(m.cellName(0)).has_value());
  EXPECT_TRUE(out.findCell("M" + std::to_string(m.cellCount() + 1)).has_value());
}

TEST(LacCutting, NewNodesGetNamesUnlikeTheOldOnes) {
  const Mesh q = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  Mesh m;
  m.setDimension(2);
  for (NodeId n = 0; n < q.nodeCount(); ++n) {
    m.addNode(q.point(n), n == 0 ? "N7" : "P" + std::to_string(n)); // N7: the first new node's name
  }
  for (CellId c = 0; c < q.cellCount(); ++c) {
    m.addCell(q.cellType(c), q.cellNodes(c));
  }
  m.setCellGroup("YMAX", *q.cellGroup("YMAX"));
  const Mesh out = cutMeshForLac(m, {"YMAX"}, LacHexaCut::Pyramids, {});
  ASSERT_EQ(out.nodeCount(), 14);
  EXPECT_EQ(out.nodeName(0), "N7");
  EXPECT_EQ(out.nodeName(6), "N7_1");
  EXPECT_EQ(out.nodeName(7), "N8");
  EXPECT_EQ(out.findNode("P3"), std::optional<NodeId>(3));
}

TEST(LacCutting, RefusesWhatItCannotCut) {
  const Mesh m = buildStructuredMesh({CellType::HEXA8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  EXPECT_THROW(cutMeshForLac(m, {"VOLUME"}, LacHexaCut::Pyramids, {}), UserError); // CREALAC_1
  Mesh inner = m;
  const NodeId face[4] = {1, 7, 10, 4};
  inner.setCellGroup("INNER", {inner.addCell(CellType::QUAD4, face)});
  try {
    cutMeshForLac(inner, {"INNER"}, LacHexaCut::Pyramids, {});
    ADD_FAILURE() << "an interior face is refused";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "CREALAC_2") << e.first().message;
  }
  const Mesh q4 = buildStructuredMesh({CellType::QUAD4, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}});
  const Mesh q9 =
      convertCells(convertCells(q4, CellConversion::LineToQuad, {}), CellConversion::Quad8To9, {});
  try {
    // Only the quadrangles made quadratic: the SEG2 of XMIN is not the QUAD8's edge.
    cutMeshForLac(convertCells(q4, CellConversion::LineToQuad, *q4.cellGroup("SURFACE")), {"XMIN"},
                  LacHexaCut::Pyramids, {});
    ADD_FAILURE() << "a SEG2 on a QUAD8 is refused";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "CREALAC_3") << e.first().message;
  }
  try {
    cutMeshForLac(q9, {"XMIN"}, LacHexaCut::Pyramids, {});
    ADD_FAILURE() << "QUAD9 in 2D is refused";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id, "CREALAC_4") << e.first().message;
    EXPECT_NE(e.first().message.find("not implemented yet"), std::string::npos);
  }
}

} // namespace
} // namespace stella
