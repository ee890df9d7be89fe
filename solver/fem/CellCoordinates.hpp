#pragma once
// The coordinates of a cell's nodes, as the element routines (fem::computeKinematics, the load
// integrals) take them.

#include "solver/mesh/Mesh.hpp"

#include <Eigen/Dense>

namespace stella {

// Coordinates of a cell's nodes as a (nodes x dim) matrix.
Eigen::MatrixXd cellCoordinates(const Mesh& mesh, CellId c, int dim);

} // namespace stella
