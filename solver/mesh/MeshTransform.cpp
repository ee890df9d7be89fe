// MODI_MAILLAGE operations (see MeshTransform.hpp).

#include "solver/mesh/MeshTransform.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace stella {

namespace {

std::vector<int> vertexReversal(CellShape s) {
  switch (s) {
  case CellShape::Point:
    return {0};
  case CellShape::Segment:
    return {1, 0};
  case CellShape::Triangle:
    return {0, 2, 1};
  case CellShape::Quadrangle:
    return {0, 3, 2, 1};
  case CellShape::Tetrahedron:
    return {0, 2, 1, 3};
  case CellShape::Pentahedron:
    return {0, 2, 1, 3, 5, 4};
  case CellShape::Pyramid:
    return {0, 3, 2, 1, 4};
  case CellShape::Hexahedron:
    return {0, 3, 2, 1, 4, 7, 6, 5};
  }
  return {};
}

std::vector<int> sortedVertices(const std::vector<int>& nodes, int nv) {
  std::vector<int> v(nodes.begin(), nodes.begin() + nv);
  std::sort(v.begin(), v.end());
  return v;
}

} // namespace

std::vector<int> orientationReversal(CellType t) {
  if (t == CellType::SEG4) {
    return {1, 0, 3, 2};
  }
  const auto p = vertexReversal(shapeOf(t));
  const int nv = vertexCount(t);
  std::vector<int> perm(static_cast<std::size_t>(nodeCount(t)));
  for (int i = 0; i < nv; ++i) {
    perm[static_cast<std::size_t>(i)] = p[static_cast<std::size_t>(i)];
  }
  const auto edges = cellEdges(t);
  for (const auto& e : edges) {
    if (e.mid < 0) {
      continue;
    }
    const int a = p[static_cast<std::size_t>(e.a)];
    const int b = p[static_cast<std::size_t>(e.b)];
    for (const auto& o : edges) {
      if ((o.a == a && o.b == b) || (o.a == b && o.b == a)) {
        perm[static_cast<std::size_t>(e.mid)] = o.mid;
      }
    }
  }
  // Face centres (PENTA18, HEXA27) and the cell centre (TRIA7, QUAD9, HEXA27) stay with their
  // face / cell.
  const auto faces = cellFaces(t);
  for (const auto& f : faces) {
    const int fv = vertexCount(f.type);
    if (static_cast<int>(f.nodes.size()) != 2 * fv + 1 || dimension(t) != 3) {
      continue;
    }
    std::vector<int> mapped;
    for (int i = 0; i < fv; ++i) {
      mapped.push_back(p[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(i)])]);
    }
    std::sort(mapped.begin(), mapped.end());
    for (const auto& o : faces) {
      if (static_cast<int>(o.nodes.size()) == 2 * fv + 1 && sortedVertices(o.nodes, fv) == mapped) {
        perm[static_cast<std::size_t>(f.nodes.back())] = o.nodes.back();
      }
    }
  }
  if (t == CellType::TRIA7 || t == CellType::QUAD9 || t == CellType::HEXA27) {
    perm.back() = nodeCount(t) - 1;
  }
  return perm;
}

void reverseCell(Mesh& mesh, CellId c) {
  const auto perm = orientationReversal(mesh.cellType(c));
  auto nodes = mesh.mutableCellNodes(c);
  const std::vector<NodeId> old(nodes.begin(), nodes.end());
  for (std::size_t i = 0; i < perm.size(); ++i) {
    nodes[i] = old[static_cast<std::size_t>(perm[i])];
  }
}

void translateMesh(Mesh& mesh, const Point3& v) {
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    mesh.setPoint(n, mesh.point(n) + v);
  }
}

void rotateMesh(Mesh& mesh, const Point3& point, const Point3& axis, double degrees) {
  const double an = norm(axis);
  if (an == 0) {
    return;
  }
  const Point3 k = (1.0 / an) * axis;
  const double th = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(th);
  const double s = std::sin(th);
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    const Point3 r = mesh.point(n) - point;
    // Rodrigues' formula.
    const Point3 rot = c * r + s * cross(k, r) + ((1 - c) * dot(k, r)) * k;
    mesh.setPoint(n, point + rot);
  }
}

void scaleMesh(Mesh& mesh, double factor) {
  for (auto& x : mesh.mutableCoordinates()) {
    x *= factor;
  }
}

void mirrorMesh(Mesh& mesh, const Point3& point, const Point3& axis1, const Point3* axis2) {
  Point3 normal;
  if (axis2 == nullptr) {
    normal = {axis1[1], -axis1[0], 0.0}; // in-plane normal of the 2D line
  } else {
    normal = cross(axis1, *axis2);
  }
  const double nn = norm(normal);
  if (nn == 0) {
    throw UserError(
        Diagnostic::fatal("MODI_MAILLAGE_2", "SYMETRIE: the axes do not define a line or a plane"));
  }
  const Point3 u = (1.0 / nn) * normal;
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    const Point3 x = mesh.point(n);
    mesh.setPoint(n, x + (-2.0 * dot(x - point, u)) * u);
  }
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    if (dimension(mesh.cellType(c)) >= 1) {
      reverseCell(mesh, c);
    }
  }
}

int orientSkin(Mesh& mesh, const std::vector<CellId>& skin, const std::vector<CellId>& volumes) {
  const int top = mesh.dimension() == 2 ? 2 : 3;
  std::vector<CellId> candidates = volumes;
  if (candidates.empty()) {
    for (CellId c = 0; c < mesh.cellCount(); ++c) {
      if (dimension(mesh.cellType(c)) == top) {
        candidates.push_back(c);
      }
    }
  }
  // Skin vertex sets we look for -> the outward vertex cycles of the matching volume faces.
  std::map<std::vector<NodeId>, std::vector<std::vector<NodeId>>> faces;
  for (const CellId s : skin) {
    const CellType t = mesh.cellType(s);
    if (dimension(t) != top - 1) {
      throw UserError(Diagnostic::fatal("ORIE_PEAU_3",
                                        "cell " + mesh.cellName(s) + " (" + std::string(name(t)) +
                                            ") is not a skin cell of a " + std::to_string(top) + "D mesh"));
    }
    const auto n = mesh.cellNodes(s);
    std::vector<NodeId> key(n.begin(), n.begin() + vertexCount(t));
    std::sort(key.begin(), key.end());
    faces.emplace(key, std::vector<std::vector<NodeId>>{});
  }
  for (const CellId v : candidates) {
    const CellType t = mesh.cellType(v);
    if (dimension(t) != top) {
      continue;
    }
    const auto n = mesh.cellNodes(v);
    for (const auto& f : cellFaces(t)) {
      const int fv = vertexCount(f.type);
      std::vector<NodeId> cycle;
      for (int i = 0; i < fv; ++i) {
        cycle.push_back(n[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(i)])]);
      }
      std::vector<NodeId> key = cycle;
      std::sort(key.begin(), key.end());
      const auto it = faces.find(key);
      if (it != faces.end()) {
        it->second.push_back(cycle);
      }
    }
  }
  int reversed = 0;
  for (const CellId s : skin) {
    const CellType t = mesh.cellType(s);
    const int nv = vertexCount(t);
    const auto n = mesh.cellNodes(s);
    std::vector<NodeId> key(n.begin(), n.begin() + nv);
    std::sort(key.begin(), key.end());
    const auto& cycles = faces[key];
    if (cycles.empty()) {
      throw UserError(
          Diagnostic::fatal("ORIE_PEAU_1", "skin cell " + mesh.cellName(s) + " bounds no volume cell")
              .withNote("a skin cell must be a face of a cell of the mesh"));
    }
    if (cycles.size() > 1) {
      throw UserError(Diagnostic::fatal("ORIE_PEAU_2", "skin cell " + mesh.cellName(s) +
                                                           " lies between two volume cells (internal skin)")
                          .withNote("give the cells of the side the normal must leave (GROUP_MA_INTERNE / "
                                    "GROUP_MA_VOLU / GROUP_MA_SURF)"));
    }
    // Same orientation when the skin's vertex cycle is a rotation of the outward face cycle.
    const auto& cycle = cycles.front();
    const auto pos = static_cast<std::size_t>(std::find(cycle.begin(), cycle.end(), n[0]) - cycle.begin());
    const bool same = nv == 2 ? cycle[0] == n[0] : cycle[(pos + 1) % cycle.size()] == n[1];
    if (!same) {
      reverseCell(mesh, s);
      ++reversed;
    }
  }
  return reversed;
}

} // namespace stella
