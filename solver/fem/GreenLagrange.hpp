#pragma once
// Total Lagrangian kinematics of COMPORTEMENT DEFORMATION='GROT_GDEP' (large displacements and
// rotations): at a Gauss point of the reference configuration, the deformation gradient
// F = I + grad_X u, the Green-Lagrange strain E = (F^T F - I) / 2, its variation dE = B_F du
// (B_F depends on F) and the geometric (initial stress) stiffness of a second Piola-Kirchhoff
// stress S: d(dE) : S. The internal forces are sum_q w_q B_F^T S and the tangent
// sum_q w_q (B_F^T D B_F + G(S)), with the weights of the reference configuration.
//
// Layouts as in Modelling.hpp: E carries engineering shears (2 E_xy), S tensor components. D_PLAN
// and C_PLAN: F_zz = 1 (C_PLAN's E_zz is the behaviour's output, it enters no in-plane force);
// AXIS: F_zz = 1 + u_r / r (hoop). Built on the small-strain ElementKinematics (whose B holds the
// reference gradients dN/dX and, in AXIS, N/r); not for the mean-dilatation ('_SI') B-bar.

#include "solver/fem/Kinematics.hpp"

#include <Eigen/Dense>

namespace stella::fem {

// The strain measure of a volume cell (COMPORTEMENT DEFORMATION): 'PETIT' or 'GROT_GDEP'.
enum class StrainMeasure { Small, GreenLagrange };

// Reference gradients at point q, read off the small-strain B: (nodeCount x 3), columns dN/dX,
// dN/dY, then dN/dZ (3D), N/r (AXIS) or 0 (D_PLAN, C_PLAN).
Eigen::MatrixXd referenceGradients(const ElementKinematics& k, int q);

// F at a point with gradients `g` for element displacements u (dofCount, node by node).
Eigen::Matrix3d deformationGradient(const ElementKinematics& k, const Eigen::Ref<const Eigen::MatrixXd>& g,
                                    const Eigen::Ref<const Eigen::VectorXd>& u);

// E = (F^T F - I) / 2 in the modelling's layout (strainSize, engineering shears).
Eigen::VectorXd greenLagrangeStrain(Modelling m, const Eigen::Matrix3d& f);

// B_F (strainSize x dofCount): dE = B_F du at the deformation gradient f.
Eigen::MatrixXd greenLagrangeVariation(const ElementKinematics& k, const Eigen::Ref<const Eigen::MatrixXd>& g,
                                       const Eigen::Matrix3d& f);

// ke += weight * G(S): G_(ia)(jb) = delta_ab grad N_i . S . grad N_j (+ S_zz N_i N_j / r^2 on the
// radial DOFs in AXIS); `stress` in the modelling's layout (tensor shears).
void addGeometricStiffness(const ElementKinematics& k, const Eigen::Ref<const Eigen::MatrixXd>& g,
                           const Eigen::Ref<const Eigen::VectorXd>& stress, double weight,
                           Eigen::MatrixXd& ke);

} // namespace stella::fem
