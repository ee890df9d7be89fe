// Reference topology of the cell types (see CellTopology.hpp for the orderings).

#include "solver/mesh/CellTopology.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>

namespace stella {

namespace {

using Pair = std::array<int, 2>;

// Vertex pairs of the edges of each shape, in code_aster's mid-node order.
std::vector<Pair> shapeEdges(CellShape s) {
  switch (s) {
  case CellShape::Point:
    return {};
  case CellShape::Segment:
    return {{0, 1}};
  case CellShape::Triangle:
    return {{0, 1}, {1, 2}, {2, 0}};
  case CellShape::Quadrangle:
    return {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  case CellShape::Tetrahedron:
    return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  case CellShape::Pentahedron:
    return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}};
  case CellShape::Pyramid:
    return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
  case CellShape::Hexahedron:
    return {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  }
  return {};
}

// Outward-oriented vertex lists of the faces of each volume shape.
std::vector<std::vector<int>> shapeFaces(CellShape s) {
  switch (s) {
  case CellShape::Tetrahedron:
    return {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  case CellShape::Pentahedron:
    return {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  case CellShape::Pyramid:
    return {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  case CellShape::Hexahedron:
    return {{0, 3, 2, 1}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  default:
    return {};
  }
}

// Vertex sets of the faces that carry a centre node, in centre-node order.
std::vector<std::vector<int>> centredFaces(CellType t) {
  switch (t) {
  case CellType::PENTA18:
    return {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
  case CellType::HEXA27:
    return {{0, 1, 2, 3}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  default:
    return {};
  }
}

bool sameSet(std::vector<int> a, std::vector<int> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

CellType faceTypeFor(int vertices, int nodes) {
  if (vertices == 3) {
    return nodes == 3 ? CellType::TRIA3 : (nodes == 6 ? CellType::TRIA6 : CellType::TRIA7);
  }
  return nodes == 4 ? CellType::QUAD4 : (nodes == 8 ? CellType::QUAD8 : CellType::QUAD9);
}

} // namespace

CellShape shapeOf(CellType t) {
  switch (t) {
  case CellType::POI1:
    return CellShape::Point;
  case CellType::SEG2:
  case CellType::SEG3:
  case CellType::SEG4:
    return CellShape::Segment;
  case CellType::TRIA3:
  case CellType::TRIA6:
  case CellType::TRIA7:
    return CellShape::Triangle;
  case CellType::QUAD4:
  case CellType::QUAD8:
  case CellType::QUAD9:
    return CellShape::Quadrangle;
  case CellType::TETRA4:
  case CellType::TETRA10:
    return CellShape::Tetrahedron;
  case CellType::PENTA6:
  case CellType::PENTA15:
  case CellType::PENTA18:
    return CellShape::Pentahedron;
  case CellType::PYRAM5:
  case CellType::PYRAM13:
    return CellShape::Pyramid;
  case CellType::HEXA8:
  case CellType::HEXA20:
  case CellType::HEXA27:
    return CellShape::Hexahedron;
  }
  return CellShape::Point;
}

int vertexCount(CellType t) {
  static constexpr std::array<int, 8> counts{1, 2, 3, 4, 4, 6, 5, 8};
  return counts[static_cast<std::size_t>(shapeOf(t))];
}

CellType linearType(CellType t) {
  static constexpr std::array<CellType, 8> types{CellType::POI1,   CellType::SEG2,   CellType::TRIA3,
                                                 CellType::QUAD4,  CellType::TETRA4, CellType::PENTA6,
                                                 CellType::PYRAM5, CellType::HEXA8};
  return types[static_cast<std::size_t>(shapeOf(t))];
}

CellType quadraticType(CellType t) {
  static constexpr std::array<CellType, 8> types{CellType::POI1,    CellType::SEG3,    CellType::TRIA6,
                                                 CellType::QUAD8,   CellType::TETRA10, CellType::PENTA15,
                                                 CellType::PYRAM13, CellType::HEXA20};
  return types[static_cast<std::size_t>(shapeOf(t))];
}

std::vector<CellEdge> cellEdges(CellType t) {
  std::vector<CellEdge> edges;
  const int nv = vertexCount(t);
  const bool hasMid = nodeCount(t) > nv && t != CellType::SEG4;
  int k = 0;
  for (const auto& p : shapeEdges(shapeOf(t))) {
    edges.push_back({p[0], p[1], hasMid ? nv + k : -1});
    ++k;
  }
  return edges;
}

std::vector<CellFace> cellFaces(CellType t) {
  const auto edges = cellEdges(t);
  const auto midOf = [&](int a, int b) {
    for (const auto& e : edges) {
      if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) {
        return e.mid;
      }
    }
    return -1;
  };
  std::vector<CellFace> faces;
  const CellShape s = shapeOf(t);
  if (s == CellShape::Triangle || s == CellShape::Quadrangle) {
    for (const auto& e : edges) {
      CellFace f{e.mid >= 0 ? CellType::SEG3 : CellType::SEG2, {e.a, e.b}};
      if (e.mid >= 0) {
        f.nodes.push_back(e.mid);
      }
      faces.push_back(std::move(f));
    }
    return faces;
  }
  const auto centred = centredFaces(t);
  for (const auto& vertices : shapeFaces(s)) {
    CellFace f{CellType::POI1, vertices};
    const int nv = static_cast<int>(vertices.size());
    if (!edges.empty() && edges.front().mid >= 0) {
      for (int i = 0; i < nv; ++i) {
        f.nodes.push_back(
            midOf(vertices[static_cast<std::size_t>(i)], vertices[static_cast<std::size_t>((i + 1) % nv)]));
      }
    }
    for (std::size_t c = 0; c < centred.size(); ++c) {
      if (sameSet(centred[c], vertices)) {
        f.nodes.push_back(vertexCount(t) + static_cast<int>(edges.size()) + static_cast<int>(c));
      }
    }
    f.type = faceTypeFor(nv, static_cast<int>(f.nodes.size()));
    faces.push_back(std::move(f));
  }
  return faces;
}

std::vector<std::array<double, 3>> referenceCoordinates(CellType t) {
  std::vector<std::array<double, 3>> x;
  switch (shapeOf(t)) {
  case CellShape::Point:
    x = {{0, 0, 0}};
    break;
  case CellShape::Segment:
    x = {{-1, 0, 0}, {1, 0, 0}};
    break;
  case CellShape::Triangle:
    x = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    break;
  case CellShape::Quadrangle:
    x = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    break;
  case CellShape::Tetrahedron:
    x = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    break;
  case CellShape::Pentahedron:
    x = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    break;
  case CellShape::Pyramid:
    x = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}};
    break;
  case CellShape::Hexahedron:
    x = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    break;
  }
  const auto mean = [&](const std::vector<int>& ids) {
    std::array<double, 3> m{0, 0, 0};
    for (int i : ids) {
      for (int d = 0; d < 3; ++d) {
        m[static_cast<std::size_t>(d)] += x[static_cast<std::size_t>(i)][static_cast<std::size_t>(d)];
      }
    }
    for (auto& v : m) {
      v /= static_cast<double>(ids.size());
    }
    return m;
  };
  const std::size_t nv = x.size();
  if (t == CellType::SEG4) {
    x.push_back({-1.0 / 3.0, 0, 0});
    x.push_back({1.0 / 3.0, 0, 0});
    return x;
  }
  if (nodeCount(t) > static_cast<int>(nv)) {
    for (const auto& e : cellEdges(t)) {
      x.push_back(mean({e.a, e.b}));
    }
  }
  for (const auto& f : centredFaces(t)) {
    x.push_back(mean(f));
  }
  if (t == CellType::TRIA7 || t == CellType::QUAD9 || t == CellType::HEXA27) {
    std::vector<int> all(nv);
    for (std::size_t i = 0; i < nv; ++i) {
      all[i] = static_cast<int>(i);
    }
    x.push_back(mean(all));
  }
  STELLA_ASSERT(static_cast<int>(x.size()) == nodeCount(t),
                "reference coordinates of " + std::string(name(t)));
  return x;
}

} // namespace stella
