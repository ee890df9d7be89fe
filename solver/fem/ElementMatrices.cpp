// Element stiffness and internal forces.

#include "solver/fem/ElementMatrices.hpp"

namespace stella::fem {

void stiffness(const ElementKinematics& k, const Eigen::Ref<const Eigen::MatrixXd>& d, Eigen::MatrixXd& out) {
  out.setZero(k.dofCount, k.dofCount);
  Eigen::MatrixXd db;
  for (int q = 0; q < k.pointCount(); ++q) {
    const auto uq = static_cast<std::size_t>(q);
    db.noalias() = d * k.b[uq];
    out.noalias() += k.weights[uq] * (k.b[uq].transpose() * db);
  }
}

void stiffness(const ElementKinematics& k, const std::vector<Eigen::MatrixXd>& tangents,
               Eigen::MatrixXd& out) {
  out.setZero(k.dofCount, k.dofCount);
  Eigen::MatrixXd db;
  for (int q = 0; q < k.pointCount(); ++q) {
    const auto uq = static_cast<std::size_t>(q);
    db.noalias() = tangents[uq] * k.b[uq];
    out.noalias() += k.weights[uq] * (k.b[uq].transpose() * db);
  }
}

void internalForces(const ElementKinematics& k, const std::vector<Eigen::VectorXd>& stresses,
                    Eigen::VectorXd& out) {
  out.setZero(k.dofCount);
  for (int q = 0; q < k.pointCount(); ++q) {
    const auto uq = static_cast<std::size_t>(q);
    out.noalias() += k.weights[uq] * (k.b[uq].transpose() * stresses[uq]);
  }
}

} // namespace stella::fem
