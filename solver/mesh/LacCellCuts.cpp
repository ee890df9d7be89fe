// The cell cuts of CREA_MAILLAGE/DECOUPE_LAC (see LacCellCuts.hpp).

#include "solver/mesh/LacCellCuts.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/CellTopology.hpp"

#include <algorithm>
#include <array>
#include <map>

namespace stella {

namespace {

using Vec = Eigen::Vector3d;

// Makes the pieces of one cut: new nodes at points of the cell's reference element, quadratic
// pieces when the cell is quadratic (mid-edge nodes shared with the cell's edges or made once).
class Cutter {
public:
  Cutter(Mesh& mesh, const LacPiece& cell, int face)
      : mesh_(mesh), cell_(cell), ref_(fem::referenceElement(cell.type)),
        quadratic_(cell.type != linearType(cell.type)) {
    for (int i = 0; i < nodeCount(cell.type); ++i) {
      const NodeId n = cell.nodes[static_cast<std::size_t>(i)];
      refOf_[n] = ref_.node(i);
      xs_.push_back(mesh.point(n));
    }
    for (const auto& e : cellEdges(cell.type)) {
      if (e.mid >= 0) {
        mids_[key(vertex(e.a), vertex(e.b))] = vertex(e.mid);
      }
    }
    const auto faces = cellFaces(cell.type);
    const auto& f = faces[static_cast<std::size_t>(face)];
    for (int i = 0; i < vertexCount(f.type); ++i) {
      faceVertices_.push_back(f.nodes[static_cast<std::size_t>(i)]);
      onFace_[vertex(f.nodes[static_cast<std::size_t>(i)])] = true;
    }
  }

  NodeId vertex(int local) const { return cell_.nodes[static_cast<std::size_t>(local)]; }
  // Local vertex indices of the slave face, outward.
  const std::vector<int>& faceVertices() const { return faceVertices_; }
  Vec refOf(NodeId n) const { return refOf_.at(n); }

  // A new node at reference point r of the cell.
  NodeId add(const Vec& r, bool onFace) {
    const Eigen::VectorXd w = ref_.values(r);
    Point3 x{0, 0, 0};
    for (std::size_t i = 0; i < xs_.size(); ++i) {
      for (std::size_t d = 0; d < 3; ++d) {
        x[d] += w(static_cast<Eigen::Index>(i)) * xs_[i][d];
      }
    }
    const NodeId n = mesh_.addNode(x);
    refOf_[n] = r;
    onFace_[n] = onFace;
    (onFace ? cut_.faceNodes : cut_.insideNodes).push_back(n);
    return n;
  }

  NodeId mid(NodeId a, NodeId b) {
    const auto k = key(a, b);
    const auto it = mids_.find(k);
    if (it != mids_.end()) {
      return it->second;
    }
    const NodeId n = add(0.5 * (refOf(a) + refOf(b)), onFace_[a] && onFace_[b]);
    mids_[k] = n;
    return n;
  }

  // A piece of the linear type `t` on `vertices` (quadratic when the cell is).
  LacPiece make(CellType t, std::vector<NodeId> vertices) {
    LacPiece p{quadratic_ ? quadraticType(t) : t, std::move(vertices)};
    if (quadratic_) {
      for (const auto& e : cellEdges(p.type)) {
        p.nodes.push_back(
            mid(p.nodes[static_cast<std::size_t>(e.a)], p.nodes[static_cast<std::size_t>(e.b)]));
      }
    }
    return p;
  }
  void addCell(CellType t, std::vector<NodeId> vertices) {
    cut_.cells.push_back(make(t, std::move(vertices)));
  }
  void addFace(CellType t, std::vector<NodeId> vertices) {
    cut_.faces.push_back(make(t, std::move(vertices)));
  }

  LacCut take() { return std::move(cut_); }

private:
  static std::pair<NodeId, NodeId> key(NodeId a, NodeId b) { return {std::min(a, b), std::max(a, b)}; }

  Mesh& mesh_;
  const LacPiece& cell_;
  const fem::ReferenceElement& ref_;
  bool quadratic_;
  std::vector<Point3> xs_;
  std::map<NodeId, Vec> refOf_;
  std::map<NodeId, bool> onFace_;
  std::map<std::pair<NodeId, NodeId>, NodeId> mids_;
  std::vector<int> faceVertices_;
  LacCut cut_;
};

std::vector<NodeId> slaveVertices(std::span<const NodeId> slaveNodes, CellType faceType) {
  return {slaveNodes.begin(), slaveNodes.begin() + vertexCount(faceType)};
}

// Cone from the centre of the slave face to every other face of the cell.
void coneCut(Cutter& k, const LacPiece& cell, int face, const std::vector<NodeId>& slave) {
  Vec centre = Vec::Zero();
  for (const int v : k.faceVertices()) {
    centre += k.refOf(k.vertex(v));
  }
  const NodeId c = k.add(centre / static_cast<double>(k.faceVertices().size()), true);
  const auto faces = cellFaces(cell.type);
  for (std::size_t g = 0; g < faces.size(); ++g) {
    if (static_cast<int>(g) == face) {
      continue;
    }
    // The outward face reversed (g0, g3, g2, g1): its normal points to the apex c.
    const auto& gn = faces[g].nodes;
    std::vector<NodeId> v{k.vertex(gn[0])};
    for (int i = vertexCount(faces[g].type) - 1; i >= 1; --i) {
      v.push_back(k.vertex(gn[static_cast<std::size_t>(i)]));
    }
    v.push_back(c);
    k.addCell(v.size() == 4 ? CellType::TETRA4 : CellType::PYRAM5, v);
  }
  const std::size_t n = slave.size();
  for (std::size_t j = 0; j < n; ++j) {
    k.addFace(CellType::TRIA3, {slave[j], slave[(j + 1) % n], c});
  }
}

// Hexahedron cut in six: f0..f3 the slave face turning around the inward normal, o0..o3 the
// vertices above them; (u,v,w) box coordinates, w = 0 on the slave face.
void hexaCut(Cutter& k, const LacPiece& cell, const std::vector<NodeId>& slave) {
  std::array<NodeId, 4> f{};
  std::array<NodeId, 4> o{};
  const auto& fv = k.faceVertices();
  for (std::size_t i = 0; i < 4; ++i) {
    const int local = fv[(4 - i) % 4]; // reversed: inward normal
    f[i] = k.vertex(local);
    for (const auto& e : cellEdges(cell.type)) {
      const int other = e.a == local ? e.b : (e.b == local ? e.a : -1);
      if (other >= 0 && std::find(fv.begin(), fv.end(), other) == fv.end()) {
        o[i] = k.vertex(other);
      }
    }
  }
  const auto box = [&](double u, double v, double w) {
    const double wf[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
    Vec r = Vec::Zero();
    for (std::size_t i = 0; i < 4; ++i) {
      r += wf[i] * ((1 - w) * k.refOf(f[i]) + w * k.refOf(o[i]));
    }
    return r;
  };
  const double uv[4][2] = {{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
  std::array<NodeId, 4> p{};
  std::array<NodeId, 4> q{};
  for (std::size_t i = 0; i < 4; ++i) {
    p[i] = k.add(box(uv[i][0], uv[i][1], 0.0), true);
  }
  for (std::size_t i = 0; i < 4; ++i) {
    q[i] = k.add(box(uv[i][0], uv[i][1], 0.5), false);
  }
  k.addCell(CellType::HEXA8, {p[0], p[1], p[2], p[3], q[0], q[1], q[2], q[3]});
  k.addCell(CellType::HEXA8, {q[0], q[1], q[2], q[3], o[0], o[1], o[2], o[3]});
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t j = (i + 1) % 4;
    k.addCell(CellType::HEXA8, {f[i], f[j], p[j], p[i], o[i], o[j], q[j], q[i]});
  }
  const auto inner = [&](NodeId s) {
    return p[static_cast<std::size_t>(std::find(f.begin(), f.end(), s) - f.begin())];
  };
  k.addFace(CellType::QUAD4, {inner(slave[0]), inner(slave[1]), inner(slave[2]), inner(slave[3])});
  for (std::size_t j = 0; j < 4; ++j) {
    const NodeId a = slave[j];
    const NodeId b = slave[(j + 1) % 4];
    k.addFace(CellType::QUAD4, {a, b, inner(b), inner(a)});
  }
}

// 2D cells, cut along their edge (a, b) taken in the cell's turning order.
void triangleCut(Cutter& k, int face, const std::vector<NodeId>& slave) {
  const NodeId a = k.vertex(face);
  const NodeId b = k.vertex((face + 1) % 3);
  const NodeId c = k.vertex((face + 2) % 3);
  const NodeId m = k.add(0.5 * (k.refOf(a) + k.refOf(b)), true);
  k.addCell(CellType::TRIA3, {a, m, c});
  k.addCell(CellType::TRIA3, {m, b, c});
  k.addFace(CellType::SEG2, {slave[0], m});
  k.addFace(CellType::SEG2, {m, slave[1]});
}

void quadrangleCut(Cutter& k, int face, const std::vector<NodeId>& slave) {
  const NodeId a = k.vertex(face);
  const NodeId b = k.vertex((face + 1) % 4);
  const NodeId c = k.vertex((face + 2) % 4);
  const NodeId d = k.vertex((face + 3) % 4);
  const auto box = [&](double u, double v) -> Vec {
    return (1 - u) * (1 - v) * k.refOf(a) + u * (1 - v) * k.refOf(b) + u * v * k.refOf(c) +
           (1 - u) * v * k.refOf(d);
  };
  const NodeId p1 = k.add(box(1.0 / 3.0, 0.0), true);
  const NodeId p2 = k.add(box(2.0 / 3.0, 0.0), true);
  const NodeId q1 = k.add(box(1.0 / 3.0, 0.5), false);
  const NodeId q2 = k.add(box(2.0 / 3.0, 0.5), false);
  k.addCell(CellType::QUAD4, {a, p1, q1, d});
  k.addCell(CellType::QUAD4, {p1, p2, q2, q1});
  k.addCell(CellType::QUAD4, {p2, b, c, q2});
  k.addCell(CellType::QUAD4, {q1, q2, c, d});
  const bool forward = slave[0] == a;
  const std::array<NodeId, 4> chain =
      forward ? std::array<NodeId, 4>{a, p1, p2, b} : std::array<NodeId, 4>{b, p2, p1, a};
  for (std::size_t i = 0; i < 3; ++i) {
    k.addFace(CellType::SEG2, {chain[i], chain[i + 1]});
  }
}

} // namespace

LacCutKind lacCutKind(CellType cell, CellType face) {
  using T = CellType;
  switch (cell) {
  case T::TRIA3:
  case T::QUAD4:
    return face == T::SEG2 ? LacCutKind::Cut : LacCutKind::Unsupported;
  case T::TRIA6:
  case T::QUAD8:
    return face == T::SEG3 ? LacCutKind::Kept : LacCutKind::Unsupported;
  case T::TETRA4:
  case T::PENTA6:
  case T::PYRAM5:
  case T::HEXA8:
    return face == T::TRIA3 || face == T::QUAD4 ? LacCutKind::Cut : LacCutKind::Unsupported;
  case T::TETRA10:
  case T::PENTA15:
  case T::PYRAM13:
  case T::HEXA20:
    return face == T::TRIA6 || face == T::QUAD8 ? LacCutKind::Cut : LacCutKind::Unsupported;
  case T::HEXA27:
    return face == T::QUAD9 ? LacCutKind::Kept : LacCutKind::Unsupported;
  default:
    return LacCutKind::Unsupported;
  }
}

LacCut cutCellForLac(Mesh& mesh, const LacPiece& cell, int face, std::span<const NodeId> slaveNodes,
                     LacHexaCut mode) {
  const auto faceType = cellFaces(cell.type)[static_cast<std::size_t>(face)].type;
  STELLA_ASSERT(lacCutKind(cell.type, faceType) == LacCutKind::Cut,
                "DECOUPE_LAC cut of a " + std::string(name(cell.type)));
  Cutter k(mesh, cell, face);
  const auto slave = slaveVertices(slaveNodes, faceType);
  switch (shapeOf(cell.type)) {
  case CellShape::Triangle:
    triangleCut(k, face, slave);
    break;
  case CellShape::Quadrangle:
    quadrangleCut(k, face, slave);
    break;
  case CellShape::Hexahedron:
    if (mode == LacHexaCut::Hexahedra) {
      hexaCut(k, cell, slave);
    } else {
      coneCut(k, cell, face, slave);
    }
    break;
  default:
    coneCut(k, cell, face, slave);
    break;
  }
  return k.take();
}

} // namespace stella
