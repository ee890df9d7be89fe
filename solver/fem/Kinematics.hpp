#pragma once
// Small-strain kinematics of one volume element: at each Gauss point of the RIGI rule, the
// integration weight (w * |det J|, times r in AXIS), the physical point and the strain-displacement
// matrix B (strainSize x nodeCount*dim, DOFs ordered node by node: DX, DY[, DZ]).

#include "solver/fem/Modelling.hpp"
#include "solver/fem/ShapeTable.hpp"

#include <Eigen/Dense>
#include <stdexcept>
#include <vector>

namespace stella::fem {

// A cell whose Jacobian is not positive at a Gauss point (3D: inverted or flat cell), vanishes or
// changes sign inside the cell (2D, where a clockwise cell is accepted), or an AXIS cell with a
// point at r <= 0. The caller names the cell.
class DegenerateElementError : public std::runtime_error {
public:
  DegenerateElementError(int gaussPoint, double detJ)
      : std::runtime_error("degenerate Jacobian at a Gauss point"), gaussPoint_(gaussPoint), detJ_(detJ) {}
  int gaussPoint() const { return gaussPoint_; }
  double jacobian() const { return detJ_; }

private:
  int gaussPoint_;
  double detJ_;
};

struct ElementKinematics {
  Modelling modelling = Modelling::ThreeD;
  VolumeStrain volumeStrain = VolumeStrain::Pointwise;
  const ShapeTable* table = nullptr;
  int nodeCount = 0;
  int dofCount = 0;
  std::vector<double> weights;         // w * |det J| (* r)
  std::vector<Eigen::Vector3d> points; // physical coordinates of the Gauss points
  std::vector<Eigen::MatrixXd> b;      // strain-displacement matrices
  int pointCount() const { return static_cast<int>(weights.size()); }
};

// Fills `out` (reusing its storage) for a cell of `type` with node coordinates `x`
// (nodeCount x spaceDimension(m)). Throws DegenerateElementError, or std::invalid_argument when
// the cell's dimension does not match the modelling. With VolumeStrain::CellMean the B matrices
// are the mean-dilatation B-bar ones (see Modelling.hpp).
void computeKinematics(CellType type, Modelling m, const Eigen::Ref<const Eigen::MatrixXd>& x,
                       ElementKinematics& out, VolumeStrain volumeStrain = VolumeStrain::Pointwise);

// Strain vector (engineering shears) at Gauss point q for element displacements u (dofCount).
inline Eigen::VectorXd strainAt(const ElementKinematics& k, int q,
                                const Eigen::Ref<const Eigen::VectorXd>& u) {
  return k.b[static_cast<std::size_t>(q)] * u;
}

} // namespace stella::fem
