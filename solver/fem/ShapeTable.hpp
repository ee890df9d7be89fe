#pragma once
// Shape functions and reference derivatives tabulated at the points of a cell type's RIGI rule,
// computed once per (cell type, role) and shared by every element of that type.

#include "solver/fem/Quadrature.hpp"
#include "solver/fem/ReferenceElement.hpp"

#include <Eigen/Dense>
#include <vector>

namespace stella::fem {

struct ShapeTable {
  CellType type;
  int nodeCount = 0;
  int dimension = 0; // of the reference cell
  const QuadratureRule* rule = nullptr;
  std::vector<Eigen::VectorXd> values;    // per point: N_i
  std::vector<Eigen::MatrixXd> gradients; // per point: dN_i/dxi_j (nodeCount x dimension)
  int pointCount() const { return rule->size(); }
};

const ShapeTable& shapeTable(CellType type, IntegrationRole role);

} // namespace stella::fem
