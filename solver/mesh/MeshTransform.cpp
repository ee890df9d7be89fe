// MODI_MAILLAGE operations (see MeshTransform.hpp).

#include "solver/mesh/MeshTransform.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/mesh/CellOrientation.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/SkinOrientation.hpp"

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
    throw UserError(msg::make("MODI_MAILLAGE_2"));
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

SkinOrientationSummary orientSkin(Mesh& mesh, const std::vector<CellId>& skinCells,
                                  const std::vector<CellId>& volumes) {
  const int top = mesh.dimension() == 2 ? 2 : 3;
  std::vector<CellId> skin = skinCells;
  std::sort(skin.begin(), skin.end());
  skin.erase(std::unique(skin.begin(), skin.end()), skin.end());
  for (const CellId s : skin) {
    const CellType t = mesh.cellType(s);
    if (dimension(t) != top - 1) {
      throw UserError(msg::make(
          "ORIE_PEAU_3",
          {{"cell_name", mesh.cellName(s)}, {"name", std::string(name(t))}, {"top", std::to_string(top)}}));
    }
  }
  const auto bounded = boundedVolumes(mesh, skin, volumes);
  SkinOrientationSummary summary;
  std::vector<bool> fixed(skin.size(), false);
  for (std::size_t i = 0; i < skin.size(); ++i) {
    const auto& sides = bounded[i];
    if (sides.size() > 1) {
      throw UserError(msg::make("ORIE_PEAU_2", {{"cell_name", mesh.cellName(skin[i])}}));
    }
    if (sides.size() == 1) {
      fixed[i] = true;
      if (!sides.front().outward) {
        reverseCell(mesh, skin[i]);
        ++summary.reversed;
      }
    }
  }
  if (std::find(fixed.begin(), fixed.end(), false) != fixed.end()) {
    summary.reversed += propagateOrientation(mesh, skin, fixed, summary.unanchored).reversed;
  }
  return summary;
}

} // namespace stella
