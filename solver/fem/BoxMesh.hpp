#pragma once
// Structured meshes of a box as plain arrays (node coordinates + connectivity), for tests and
// benchmarks of the finite-element kernel before the mesh model exists: a grid of hexahedra
// (quadrangles in 2D) cut into the requested cell type (TETRA: 6 per hexahedron, PENTA: 2,
// PYRAM: 6 around the centre, TRIA: 2 per quadrangle), quadratic nodes placed on straight edges.
// Nodes shared by neighbouring cells are merged; cells are positively oriented.

#include "solver/mesh/CellType.hpp"

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <vector>

namespace stella {
class Mesh;
}

namespace stella::fem {

struct PlainMesh {
  int dimension = 3;
  CellType cellType = CellType::HEXA8;
  Eigen::MatrixXd coordinates;   // nodeCount x dimension
  std::vector<int> connectivity; // cellCount x nodesPerCell, code_aster order
  int nodesPerCell() const { return stella::nodeCount(cellType); }
  int cellCount() const { return static_cast<int>(connectivity.size()) / nodesPerCell(); }
  int nodeCount() const { return static_cast<int>(coordinates.rows()); }
  const int* cell(int c) const {
    return connectivity.data() + static_cast<std::ptrdiff_t>(c) * nodesPerCell();
  }
};

// Box [0, lengths[0]] x [0, lengths[1]] (x [0, lengths[2]]) with divisions[i] hexahedra
// (quadrangles) along each axis, cut into cells of `type` (2D types give a 2D mesh).
PlainMesh boxMesh(CellType type, std::array<int, 3> divisions, std::array<double, 3> lengths);

// The same nodes and cells as a Mesh (node i and cell c of `p` are node i and cell c; default
// names N1..., M1...), for the tests and benchmarks that go through the model layers.
std::shared_ptr<Mesh> toMesh(const PlainMesh& p);

} // namespace stella::fem
