#pragma once
// Loads integrated on cells: pressure along the skin normal (AFFE_CHAR_MECA PRES_REP) on 2D
// edges, axisymmetric edges (weight r, per radian) and 3D faces; distributed forces on skins
// (FORCE_CONTOUR, FORCE_FACE); volume forces (FORCE_INTERNE, PESANTEUR = rho g).
//
// The skin normal follows the cell's node ordering: for an edge in the plane with tangent
// t = dx/dxi, n = (t_y, -t_x) (outward when the domain lies on the left of the edge); for a face,
// n = dx/dxi x dx/deta (outward when the nodes turn counter-clockwise seen from outside).
// A positive pressure pushes along -n, into the material. Vectors are per node: (FX, FY[, FZ]).

#include "solver/fem/Modelling.hpp"
#include "solver/mesh/CellType.hpp"

#include <Eigen/Dense>

namespace stella::loads {

// Unit outward normal n and area element dS/dxi at the skin's Gauss point q.
struct SkinPoint {
  Eigen::Vector3d point;  // physical coordinates
  Eigen::Vector3d normal; // unit normal (z = 0 in 2D)
  double weight = 0.0;    // w * |dS/dxi| (* r in AXIS)
  Eigen::VectorXd values; // shape functions
};

// Geometry of a skin cell (SEG2/SEG3 in 2D, TRIA3/6, QUAD4/8/9 in 3D) at its RIGI skin points.
std::vector<SkinPoint> skinPoints(CellType type, fem::Modelling m,
                                  const Eigen::Ref<const Eigen::MatrixXd>& x);

// PRES_REP: nodal pressures p (nodeCount) interpolated on the skin; returns nodeCount*dim forces.
Eigen::VectorXd pressureForces(CellType type, fem::Modelling m, const Eigen::Ref<const Eigen::MatrixXd>& x,
                               const Eigen::Ref<const Eigen::VectorXd>& nodalPressure);

// FORCE_CONTOUR / FORCE_FACE: a constant force per unit area (dim components).
Eigen::VectorXd surfaceForces(CellType type, fem::Modelling m, const Eigen::Ref<const Eigen::MatrixXd>& x,
                              const Eigen::Ref<const Eigen::VectorXd>& force);

// FORCE_INTERNE / PESANTEUR: a constant force per unit volume (dim components) on a volume cell.
Eigen::VectorXd volumeForces(CellType type, fem::Modelling m, const Eigen::Ref<const Eigen::MatrixXd>& x,
                             const Eigen::Ref<const Eigen::VectorXd>& force);

} // namespace stella::loads
