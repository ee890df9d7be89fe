#pragma once
// Test surfaces of the pairing: structured grids of any contact cell type mapped by a function
// (flat, wavy, cylindrical), curves of SEG2/SEG3, and clouds of random slave nodes.

#include "solver/contact/ContactPairing.hpp"

#include <functional>
#include <random>
#include <vector>

namespace stella::contact::testing {

using SurfaceMap = std::function<Point3(double, double)>;

// An nu x nv grid of `type` cells (QUAD4/QUAD8/QUAD9/TRIA3/TRIA6) over (u, v) in [0, 1]^2 mapped
// by f; the quadratic cells' nodes are those of the doubled lattice.
inline std::vector<CellId> surfaceGrid(Mesh& mesh, CellType type, int nu, int nv, const SurfaceMap& f) {
  const bool quadratic = type == CellType::QUAD8 || type == CellType::QUAD9 || type == CellType::TRIA6;
  const int q = quadratic ? 2 : 1;
  const NodeId base = mesh.nodeCount();
  for (int j = 0; j <= q * nv; ++j) {
    for (int i = 0; i <= q * nu; ++i) {
      mesh.addNode(f(static_cast<double>(i) / (q * nu), static_cast<double>(j) / (q * nv)));
    }
  }
  auto at = [&](int i, int j) { return base + j * (q * nu + 1) + i; };
  std::vector<CellId> cells;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const int a = q * i;
      const int b = q * j;
      switch (type) {
      case CellType::QUAD4:
        cells.push_back(
            mesh.addCell(type, std::vector<NodeId>{at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)}));
        break;
      case CellType::QUAD8:
      case CellType::QUAD9: {
        std::vector<NodeId> n{at(a, b),     at(a + 2, b),     at(a + 2, b + 2), at(a, b + 2),
                              at(a + 1, b), at(a + 2, b + 1), at(a + 1, b + 2), at(a, b + 1)};
        if (type == CellType::QUAD9) {
          n.push_back(at(a + 1, b + 1));
        }
        cells.push_back(mesh.addCell(type, n));
        break;
      }
      case CellType::TRIA3:
        cells.push_back(mesh.addCell(type, std::vector<NodeId>{at(a, b), at(a + 1, b), at(a + 1, b + 1)}));
        cells.push_back(mesh.addCell(type, std::vector<NodeId>{at(a, b), at(a + 1, b + 1), at(a, b + 1)}));
        break;
      case CellType::TRIA6:
        cells.push_back(
            mesh.addCell(type, std::vector<NodeId>{at(a, b), at(a + 2, b), at(a + 2, b + 2), at(a + 1, b),
                                                   at(a + 2, b + 1), at(a + 1, b + 1)}));
        cells.push_back(
            mesh.addCell(type, std::vector<NodeId>{at(a, b), at(a + 2, b + 2), at(a, b + 2), at(a + 1, b + 1),
                                                   at(a + 1, b + 2), at(a, b + 1)}));
        break;
      default:
        break;
      }
    }
  }
  return cells;
}

// n SEG2 or SEG3 cells along u in [0, 1] mapped by f(u, 0) (a 2D mesh).
inline std::vector<CellId> curve(Mesh& mesh, CellType type, int n, const SurfaceMap& f) {
  const int q = type == CellType::SEG3 ? 2 : 1;
  const NodeId base = mesh.nodeCount();
  for (int i = 0; i <= q * n; ++i) {
    mesh.addNode(f(static_cast<double>(i) / (q * n), 0.0));
  }
  std::vector<CellId> cells;
  for (int i = 0; i < n; ++i) {
    if (q == 2) {
      cells.push_back(
          mesh.addCell(type, std::vector<NodeId>{base + 2 * i, base + 2 * i + 2, base + 2 * i + 1}));
    } else {
      cells.push_back(mesh.addCell(type, std::vector<NodeId>{base + i, base + i + 1}));
    }
  }
  return cells;
}

// `count` disjoint TRIA3 cells whose 3 nodes are random points of the box [lo, hi] (3D), or
// SEG2 cells with z = 0 (2D): every node a slave node at a random place.
inline std::vector<CellId> randomNodes(Mesh& mesh, int count, const Point3& lo, const Point3& hi,
                                       std::mt19937& rng, bool segments = false) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto point = [&] {
    Point3 p;
    for (std::size_t a = 0; a < 3; ++a) {
      p[a] = lo[a] + (hi[a] - lo[a]) * u(rng);
    }
    if (segments) {
      p[2] = 0.0;
    }
    return p;
  };
  std::vector<CellId> cells;
  for (int k = 0; k < count; ++k) {
    std::vector<NodeId> nodes;
    for (int i = 0; i < (segments ? 2 : 3); ++i) {
      nodes.push_back(mesh.addNode(point()));
    }
    cells.push_back(mesh.addCell(segments ? CellType::SEG2 : CellType::TRIA3, nodes));
  }
  return cells;
}

inline ContactZone zoneOf(const std::string& master, const std::string& slave) {
  ContactZone z;
  z.masterGroup = master;
  z.slaveGroup = slave;
  return z;
}

} // namespace stella::contact::testing
