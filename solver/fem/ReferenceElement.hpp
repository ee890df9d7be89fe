#pragma once
// Reference elements in code_aster's node orderings and reference coordinates (R3.01.01):
// node coordinates, shape functions and their derivatives for every volume and skin cell type
// (SEG2 ... HEXA27, pyramids included).
//
// Each element's shape functions span a fixed space of functions (monomials; for pyramids also
// rational terms in 1/(1-z)); the functions are the nodal (Lagrange) basis of that space, found
// once by inverting the matrix of the space's functions at the nodes. Kronecker property and
// partition of unity hold by construction and are checked by the tests.

#include "solver/mesh/CellType.hpp"

#include <Eigen/Dense>
#include <vector>

namespace stella::fem {

class ReferenceElement {
public:
  CellType type() const { return type_; }
  int dimension() const { return dimension_; }
  int nodeCount() const { return static_cast<int>(nodes_.size()); }
  // Reference coordinates of node i (unused components are 0).
  const Eigen::Vector3d& node(int i) const { return nodes_[static_cast<std::size_t>(i)]; }
  // Measure of the reference cell (length, area, volume).
  double measure() const { return measure_; }

  // Shape function values N_i(xi), i = 0..nodeCount-1.
  Eigen::VectorXd values(const Eigen::Vector3d& xi) const;
  // Derivatives dN_i/dxi_j as a nodeCount x dimension matrix.
  Eigen::MatrixXd gradients(const Eigen::Vector3d& xi) const;

  // The linear cell type with the same vertices (HEXA20 -> HEXA8), for geometry helpers.
  CellType linearType() const;

  ReferenceElement(CellType type, int dimension, std::vector<Eigen::Vector3d> nodes, double measure);

private:
  void evaluate(const Eigen::Vector3d& xi, Eigen::VectorXd* values, Eigen::MatrixXd* gradients) const;

  CellType type_;
  int dimension_;
  std::vector<Eigen::Vector3d> nodes_;
  double measure_;
  Eigen::MatrixXd coefficients_; // basis functions -> nodal functions
};

// The reference element of a cell type (built once, thread-safe). POI1, TRIA7 and SEG4 are
// refused (std::invalid_argument): no mechanical element of stella uses them yet.
const ReferenceElement& referenceElement(CellType type);

} // namespace stella::fem
