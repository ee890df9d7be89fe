#pragma once
// Gauss points -> cell nodes: the matrix that turns values at the points of a cell type's RIGI
// rule into values at the cell's nodes, built the way code_aster builds its "MGANO" matrix for
// the ELNO options (SIEF_ELNO, EPSI_ELNO, VARI_ELNO...):
//   - one Gauss point: every node takes the point's value;
//   - otherwise the vertex values are the least-squares fit, over the Gauss points, of the
//     field interpolated by the LINEAR cell of the same shape (HEXA8 for HEXA20/HEXA27, TRIA3 for
//     TRIA6...): with A(g, i) = N_i^lin(xi_g), vertex values = (A^T A)^-1 A^T g. When the rule
//     has as many points as the cell has vertices (QUAD4/FPG4, HEXA8/FPG8, TETRA4...) this is
//     the inverse of the shape matrix, i.e. exact interpolation;
//   - a mid-edge, mid-face or centre node takes the linear interpolation of the vertex values
//     at its reference position (1/2 of each end of an edge, 1/4 of each vertex of a quadrangle
//     face, 1/8 of each vertex for the HEXA27 centre).
// Constant and (for linear cells) linear fields are reproduced exactly; tests check both.

#include "solver/fem/Quadrature.hpp"
#include "solver/mesh/CellType.hpp"

#include <Eigen/Dense>

namespace stella::fem {

// nodeCount x pointCount matrix for the RIGI rule of `type` in `role` (cached, thread-safe).
const Eigen::MatrixXd& gaussToNodeMatrix(CellType type, IntegrationRole role);

// The same matrix for any rule of the cell type's reference shape.
Eigen::MatrixXd buildGaussToNodeMatrix(CellType type, const QuadratureRule& rule);

} // namespace stella::fem
