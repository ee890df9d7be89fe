// Green-Lagrange strain, its variation and the geometric stiffness (total Lagrangian, GROT_GDEP).

#include "solver/fem/GreenLagrange.hpp"

namespace stella::fem {

Eigen::MatrixXd referenceGradients(const ElementKinematics& k, int q) {
  const Eigen::MatrixXd& b = k.b[static_cast<std::size_t>(q)];
  const int dim = spaceDimension(k.modelling);
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(k.nodeCount, 3);
  for (int i = 0; i < k.nodeCount; ++i) {
    const int c = dim * i;
    g(i, 0) = b(0, c);
    g(i, 1) = b(1, c + 1);
    g(i, 2) = dim == 3 ? b(2, c + 2) : (k.modelling == Modelling::Axisymmetric ? b(2, c) : 0.0);
  }
  return g;
}

Eigen::Matrix3d deformationGradient(const ElementKinematics& k, const Eigen::Ref<const Eigen::MatrixXd>& g,
                                    const Eigen::Ref<const Eigen::VectorXd>& u) {
  const int dim = spaceDimension(k.modelling);
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
  for (int i = 0; i < k.nodeCount; ++i) {
    for (int a = 0; a < dim; ++a) {
      const double ua = u(dim * i + a);
      for (int j = 0; j < dim; ++j) {
        f(a, j) += ua * g(i, j);
      }
    }
    if (k.modelling == Modelling::Axisymmetric) {
      f(2, 2) += u(dim * i) * g(i, 2); // u_r / r
    }
  }
  return f;
}

Eigen::VectorXd greenLagrangeStrain(Modelling m, const Eigen::Matrix3d& f) {
  const Eigen::Matrix3d e = 0.5 * (f.transpose() * f - Eigen::Matrix3d::Identity());
  if (m == Modelling::ThreeD) {
    Eigen::VectorXd v(6);
    v << e(0, 0), e(1, 1), e(2, 2), 2.0 * e(0, 1), 2.0 * e(0, 2), 2.0 * e(1, 2);
    return v;
  }
  Eigen::VectorXd v(4);
  v << e(0, 0), e(1, 1), m == Modelling::Axisymmetric ? e(2, 2) : 0.0, 2.0 * e(0, 1);
  return v;
}

Eigen::MatrixXd greenLagrangeVariation(const ElementKinematics& k, const Eigen::Ref<const Eigen::MatrixXd>& g,
                                       const Eigen::Matrix3d& f) {
  const int dim = spaceDimension(k.modelling);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(strainSize(k.modelling), k.dofCount);
  for (int i = 0; i < k.nodeCount; ++i) {
    for (int a = 0; a < dim; ++a) {
      const int c = dim * i + a;
      // dE_jl = (F_aj dN_i/dX_l + F_al dN_i/dX_j) / 2 for a displacement of node i along a
      b(0, c) = f(a, 0) * g(i, 0);
      b(1, c) = f(a, 1) * g(i, 1);
      b(3, c) = f(a, 0) * g(i, 1) + f(a, 1) * g(i, 0);
      if (dim == 3) {
        b(2, c) = f(a, 2) * g(i, 2);
        b(4, c) = f(a, 0) * g(i, 2) + f(a, 2) * g(i, 0);
        b(5, c) = f(a, 1) * g(i, 2) + f(a, 2) * g(i, 1);
      }
    }
    if (k.modelling == Modelling::Axisymmetric) {
      b(2, dim * i) = f(2, 2) * g(i, 2); // dE_zz = F_zz N_i / r du_r
    }
  }
  return b;
}

void addGeometricStiffness(const ElementKinematics& k, const Eigen::Ref<const Eigen::MatrixXd>& g,
                           const Eigen::Ref<const Eigen::VectorXd>& stress, double weight,
                           Eigen::MatrixXd& ke) {
  const int dim = spaceDimension(k.modelling);
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  s(0, 0) = stress(0);
  s(1, 1) = stress(1);
  s(0, 1) = s(1, 0) = stress(3);
  if (dim == 3) {
    s(2, 2) = stress(2);
    s(0, 2) = s(2, 0) = stress(4);
    s(1, 2) = s(2, 1) = stress(5);
  }
  const Eigen::MatrixXd gs = g.leftCols(dim);
  const Eigen::MatrixXd gg = weight * gs * s.topLeftCorner(dim, dim) * gs.transpose();
  for (int i = 0; i < k.nodeCount; ++i) {
    for (int j = 0; j < k.nodeCount; ++j) {
      for (int a = 0; a < dim; ++a) {
        ke(dim * i + a, dim * j + a) += gg(i, j);
      }
      if (k.modelling == Modelling::Axisymmetric) {
        ke(dim * i, dim * j) += weight * stress(2) * g(i, 2) * g(j, 2);
      }
    }
  }
}

} // namespace stella::fem
