#pragma once
// The elastic stiffness of the unit cube in HEXA8 (E = 210000, nu = 0.3), face x = 0 clamped by
// elimination (rows and columns zeroed, unit diagonal: symmetric positive definite, upper
// triangle), unit nodal forces FY on x = 1: the 3D study of doc/bench/fem-performance.md
// (3 (N+1)^3 equations for N hexahedra per side) without the command layer.

#include "solver/linalg/SparseMatrix.hpp"

#include <Eigen/Dense>

namespace stella::bench {

struct CubeSystem {
  linalg::SparseMatrix k;
  Eigen::VectorXd f;
};

CubeSystem hexa8Cube(int divisions);

} // namespace stella::bench
