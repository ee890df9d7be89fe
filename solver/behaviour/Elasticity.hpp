#pragma once
// Isotropic linear elasticity (DEFI_MATERIAU ELAS: E, NU) as stiffness matrices in the strain
// layout of each modelling (engineering shears, see fem/Modelling.hpp).

#include "solver/fem/Modelling.hpp"

#include <Eigen/Dense>

namespace stella::behaviour {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

struct ElasticParameters {
  double youngModulus = 0.0; // E
  double poissonRatio = 0.0; // NU
  double lameLambda() const {
    return youngModulus * poissonRatio / ((1.0 + poissonRatio) * (1.0 - 2.0 * poissonRatio));
  }
  double shearModulus() const { return youngModulus / (2.0 * (1.0 + poissonRatio)); }
  double bulkModulus() const { return youngModulus / (3.0 * (1.0 - 2.0 * poissonRatio)); }
};

// 6x6 3D stiffness (XX, YY, ZZ, XY, XZ, YZ), engineering shear strains.
Matrix6 isotropicStiffness(const ElasticParameters& p);

// The stiffness in a modelling's layout: 6x6 in 3D; 4x4 (XX, YY, ZZ, XY) in D_PLAN and AXIS;
// in C_PLAN the plane-stress condensed 4x4 with a zero ZZ row and column (sigma_zz = 0).
Eigen::MatrixXd elasticMatrix(fem::Modelling m, const ElasticParameters& p);

// Reduces a 6x6 3D tangent to a modelling's layout (C_PLAN: static condensation of ZZ).
Eigen::MatrixXd reduceTangent(fem::Modelling m, const Matrix6& t);

} // namespace stella::behaviour
