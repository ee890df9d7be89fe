#pragma once
// Element integrals built on the kinematics: stiffness B^T D B and internal forces B^T sigma,
// summed over the Gauss points with their weights.

#include "solver/fem/Kinematics.hpp"

#include <Eigen/Dense>
#include <vector>

namespace stella::fem {

// K = sum_q w_q B_q^T D B_q with one constant D (strainSize x strainSize), e.g. elasticity.
void stiffness(const ElementKinematics& k, const Eigen::Ref<const Eigen::MatrixXd>& d, Eigen::MatrixXd& out);

// K = sum_q w_q B_q^T D_q B_q with one tangent per Gauss point (may be unsymmetric).
void stiffness(const ElementKinematics& k, const std::vector<Eigen::MatrixXd>& tangents,
               Eigen::MatrixXd& out);

// F = sum_q w_q B_q^T sigma_q; stresses per Gauss point, strainSize components each.
void internalForces(const ElementKinematics& k, const std::vector<Eigen::VectorXd>& stresses,
                    Eigen::VectorXd& out);

} // namespace stella::fem
