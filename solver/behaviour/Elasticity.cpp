// Isotropic elasticity matrices.

#include "solver/behaviour/Elasticity.hpp"

namespace stella::behaviour {

Matrix6 isotropicStiffness(const ElasticParameters& p) {
  const double l = p.lameLambda();
  const double mu = p.shearModulus();
  Matrix6 d = Matrix6::Zero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      d(i, j) = l + (i == j ? 2.0 * mu : 0.0);
    }
    d(3 + i, 3 + i) = mu;
  }
  return d;
}

Eigen::MatrixXd reduceTangent(fem::Modelling m, const Matrix6& t) {
  if (m == fem::Modelling::ThreeD) {
    return t;
  }
  Eigen::MatrixXd r = t.topLeftCorner(4, 4);
  if (m == fem::Modelling::PlaneStress) {
    // sigma_zz = 0: eliminate eps_zz, D_ab - D_a2 D_2b / D_22
    const double d22 = t(2, 2);
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        r(a, b) = (a == 2 || b == 2) ? 0.0 : t(a, b) - t(a, 2) * t(2, b) / d22;
      }
    }
  }
  return r;
}

Eigen::MatrixXd elasticMatrix(fem::Modelling m, const ElasticParameters& p) {
  return reduceTangent(m, isotropicStiffness(p));
}

} // namespace stella::behaviour
