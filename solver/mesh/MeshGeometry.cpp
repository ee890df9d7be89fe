// Cell geometry from vertices (see MeshGeometry.hpp).

#include "solver/mesh/MeshGeometry.hpp"

#include "solver/mesh/CellTopology.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace stella {

namespace {

// For each vertex with three edges, its three neighbours ordered for a positive triple product
// on the reference cell; computed once per type.
std::vector<std::array<int, 4>> computeCornerFrames(CellType t) {
  std::vector<std::array<int, 4>> frames;
  const auto x = referenceCoordinates(t);
  const auto edges = cellEdges(t);
  for (int v = 0; v < vertexCount(t); ++v) {
    std::vector<int> nb;
    for (const auto& e : edges) {
      if (e.a == v) {
        nb.push_back(e.b);
      } else if (e.b == v) {
        nb.push_back(e.a);
      }
    }
    if (nb.size() != 3) {
      continue;
    }
    const auto& p = x[static_cast<std::size_t>(v)];
    const Point3 a = x[static_cast<std::size_t>(nb[0])] - p;
    const Point3 b = x[static_cast<std::size_t>(nb[1])] - p;
    const Point3 c = x[static_cast<std::size_t>(nb[2])] - p;
    if (dot(cross(a, b), c) < 0) {
      std::swap(nb[1], nb[2]);
    }
    frames.push_back({v, nb[0], nb[1], nb[2]});
  }
  return frames;
}

const std::vector<std::array<int, 4>>& cornerFrames(CellType t) {
  static const auto table = [] {
    std::array<std::vector<std::array<int, 4>>, cellTypeCount> all;
    for (const auto& i : cellTypeTable) {
      if (i.dimension == 3) {
        all[static_cast<std::size_t>(i.type)] = computeCornerFrames(i.type);
      }
    }
    return all;
  }();
  return table[static_cast<std::size_t>(t)];
}

Point3 newell(const Mesh& mesh, std::span<const NodeId> nodes, int nv) {
  Point3 n{0, 0, 0};
  for (int i = 0; i < nv; ++i) {
    const Point3 a = mesh.point(nodes[static_cast<std::size_t>(i)]);
    const Point3 b = mesh.point(nodes[static_cast<std::size_t>((i + 1) % nv)]);
    n = n + cross(a, b);
  }
  return 0.5 * n;
}

} // namespace

Point3 cellCentroid(const Mesh& mesh, CellId c) {
  const auto nodes = mesh.cellNodes(c);
  const int nv = vertexCount(mesh.cellType(c));
  Point3 m{0, 0, 0};
  for (int i = 0; i < nv; ++i) {
    m = m + mesh.point(nodes[static_cast<std::size_t>(i)]);
  }
  return (1.0 / nv) * m;
}

double cellMeasure(const Mesh& mesh, CellId c) {
  const CellType t = mesh.cellType(c);
  const auto nodes = mesh.cellNodes(c);
  switch (dimension(t)) {
  case 1:
    return norm(mesh.point(nodes[1]) - mesh.point(nodes[0]));
  case 2:
    return norm(newell(mesh, nodes, vertexCount(t)));
  case 3: {
    // Divergence theorem over the outward faces, each split in a fan of triangles.
    const Point3 o = cellCentroid(mesh, c);
    double v = 0;
    for (const auto& f : cellFaces(t)) {
      const int nv = vertexCount(f.type);
      const Point3 a = mesh.point(nodes[static_cast<std::size_t>(f.nodes[0])]) - o;
      for (int i = 1; i + 1 < nv; ++i) {
        const Point3 b =
            mesh.point(nodes[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(i)])]) - o;
        const Point3 d =
            mesh.point(nodes[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(i + 1)])]) - o;
        v += dot(a, cross(b, d)) / 6.0;
      }
    }
    return v;
  }
  default:
    return 0.0;
  }
}

Point3 cellNormal(const Mesh& mesh, CellId c) {
  const CellType t = mesh.cellType(c);
  const auto nodes = mesh.cellNodes(c);
  if (dimension(t) == 2) {
    return newell(mesh, nodes, vertexCount(t));
  }
  if (dimension(t) == 1) {
    const Point3 d = mesh.point(nodes[1]) - mesh.point(nodes[0]);
    return {d[1], -d[0], 0.0};
  }
  return {0, 0, 0};
}

std::vector<double> cornerJacobians(const Mesh& mesh, CellId c) {
  const CellType t = mesh.cellType(c);
  const auto nodes = mesh.cellNodes(c);
  std::vector<double> j;
  const auto at = [&](int i) { return mesh.point(nodes[static_cast<std::size_t>(i)]); };
  if (dimension(t) == 3) {
    for (const auto& f : cornerFrames(t)) {
      const Point3 p = at(f[0]);
      j.push_back(dot(cross(at(f[1]) - p, at(f[2]) - p), at(f[3]) - p));
    }
  } else if (dimension(t) == 2) {
    const int nv = vertexCount(t);
    for (int i = 0; i < nv; ++i) {
      const Point3 p = at(i);
      j.push_back(cross(at((i + 1) % nv) - p, at((i + nv - 1) % nv) - p)[2]);
    }
  }
  return j;
}

bool isInverted(const Mesh& mesh, CellId c) {
  const auto j = cornerJacobians(mesh, c);
  const bool negative = std::any_of(j.begin(), j.end(), [](double v) { return v < 0; });
  if (dimension(mesh.cellType(c)) == 3) {
    return negative;
  }
  return negative && std::any_of(j.begin(), j.end(), [](double v) { return v > 0; });
}

int cellWinding(const Mesh& mesh, CellId c) {
  const CellType t = mesh.cellType(c);
  if (dimension(t) == 2) {
    return cellNormal(mesh, c)[2] < 0.0 ? -1 : 1;
  }
  return dimension(t) == 3 && cellMeasure(mesh, c) < 0.0 ? -1 : 1;
}

double aspectRatio(const Mesh& mesh, CellId c) {
  const auto nodes = mesh.cellNodes(c);
  double lo = std::numeric_limits<double>::infinity();
  double hi = 0;
  for (const auto& e : cellEdges(mesh.cellType(c))) {
    const double l = norm(mesh.point(nodes[static_cast<std::size_t>(e.b)]) -
                          mesh.point(nodes[static_cast<std::size_t>(e.a)]));
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  if (hi == 0 && lo == 0) {
    return std::numeric_limits<double>::infinity();
  }
  return lo > 0 ? hi / lo : std::numeric_limits<double>::infinity();
}

} // namespace stella
