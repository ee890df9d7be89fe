// Continuous contact at integration points (ContinuousPointContact.hpp): the system of the
// multipliers (correct()) and its dense form for the unit tests.

#include "solver/contact/ContinuousPointContact.hpp"

namespace stella::contact {

ContinuousPointContactConstraint::MultiplierSystem
ContinuousPointContactConstraint::multiplierSystem(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                                                   const std::vector<char>& status) const {
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  const Eigen::Index nu = frictionUnknowns() ? (1 + tangentComponents()) * nm : nm;
  MultiplierSystem sys;
  sys.row.resize(static_cast<std::size_t>(nu));
  sys.column.resize(static_cast<std::size_t>(nu));
  sys.mass = Eigen::MatrixXd::Zero(nu, nu);
  sys.residual = Eigen::VectorXd::Zero(nu);
  sys.used.assign(static_cast<std::size_t>(nu), 0);
  normalEquations(u, ddu, status, sys);
  frictionEquations(u, ddu, status, sys);
  return sys;
}

ContinuousPointContactConstraint::Linearisation
ContinuousPointContactConstraint::linearisation(const Eigen::VectorXd& u) {
  status_ = statusAt(u);
  useInitial_ = false;
  const MultiplierSystem sys = multiplierSystem(u, Eigen::VectorXd::Zero(u.size()), status_);
  const auto nu = static_cast<Eigen::Index>(sys.row.size());
  Linearisation out;
  out.residual = sys.residual;
  out.mass = sys.mass;
  out.row = Eigen::MatrixXd::Zero(nu, u.size());
  out.column = Eigen::MatrixXd::Zero(nu, u.size());
  for (Eigen::Index i = 0; i < nu; ++i) {
    for (const auto& [e, a] : sys.row[static_cast<std::size_t>(i)]) {
      out.row(i, e) += a;
      out.column(i, e) += a;
    }
    for (const auto& [e, a] : sys.column[static_cast<std::size_t>(i)]) {
      out.column(i, e) += a;
    }
  }
  return out;
}

Eigen::VectorXd ContinuousPointContactConstraint::multipliers() {
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  Eigen::VectorXd v(frictionUnknowns() ? (1 + tangentComponents()) * nm : nm);
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    v(i) = multiplierValue(i);
  }
  return v;
}

void ContinuousPointContactConstraint::setMultipliers(const Eigen::VectorXd& values) {
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    multiplierValue(i) = values(i);
  }
}

} // namespace stella::contact
