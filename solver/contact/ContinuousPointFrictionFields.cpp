// Coulomb friction of the continuous contact at integration points (ContinuousPointContact.hpp): the
// friction loop on the points' thresholds, the nodal friction states (CONT_NOEU) and LAGS_F.

#include "solver/contact/ContinuousPointContact.hpp"

#include "solver/contact/ContactResultField.hpp"
#include "solver/database/Result.hpp"

#include <algorithm>
#include <cmath>

namespace stella::contact {

void ContinuousPointContactConstraint::resetFrictionStep() {
  if (!friction()) {
    return;
  }
  threshold_.assign(points_.size(), 0.0);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    threshold_[q] = std::max(0.0, -lambdaAt(points_[q])); // the pressure at the start of the step
  }
  frictionIterations_ = 0;
  lastThreshold_.clear();
}

void ContinuousPointContactConstraint::recordThreshold() {
  if (!friction()) {
    return;
  }
  lastThreshold_.assign(points_.size(), 0.0);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    lastThreshold_[q] = std::max(0.0, -lambdaAt(points_[q]));
  }
}

double ContinuousPointContactConstraint::frictionCriterion() const {
  const std::vector<double>& before =
      definition_->settings.continuous.frictionFixedPoint ? threshold_ : lastThreshold_;
  if (before.empty()) {
    return -1.0;
  }
  const auto n = static_cast<Eigen::Index>(points_.size());
  Eigen::VectorXd was(n);
  Eigen::VectorXd now(n);
  for (Eigen::Index q = 0; q < n; ++q) {
    now(q) = std::max(0.0, -lambdaAt(points_[static_cast<std::size_t>(q)]));
    was(q) = before[static_cast<std::size_t>(q)];
  }
  return frictionThresholdChange(was, now);
}

bool ContinuousPointContactConstraint::acceptFriction(const Eigen::VectorXd& u) {
  const FrictionLoop step =
      frictionLoopStep(definition_->settings.continuous, frictionCriterion(), frictionIterations_, time_,
                       definition_->location, " of the contact points", continuation_);
  if (step != FrictionLoop::NewThreshold) {
    return step == FrictionLoop::Accept;
  }
  for (std::size_t q = 0; q < points_.size(); ++q) {
    threshold_[q] = std::max(0.0, -lambdaAt(points_[q]));
  }
  status_ = statusAt(u); // the stick/slip status under the new threshold
  lastStatus_ = status_;
  return false;
}

void ContinuousPointContactConstraint::nodalFriction(const Eigen::VectorXd& u,
                                                     const std::vector<char>& status,
                                                     std::vector<Eigen::Vector3d>& force,
                                                     std::vector<char>& sliding) const {
  force.assign(multiplierNode_.size(), Eigen::Vector3d::Zero());
  sliding.assign(multiplierNode_.size(), 0);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (!p.paired || status[q] == 0) {
      continue;
    }
    const Eigen::Vector2d pt = tangentialPressureAt(q, status[q], u);
    const Eigen::Vector3d along = pt(0) * p.direction[0] + pt(1) * p.direction[1];
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const int i = p.multiplier[k];
      if (i >= 0 && p.shape[k] != 0.0) {
        force[static_cast<std::size_t>(i)] -= p.weight * p.shape[k] * along;
        sliding[static_cast<std::size_t>(i)] =
            sliding[static_cast<std::size_t>(i)] != 0 || status[q] >= 2 ? 1 : 0;
      }
    }
  }
}

void ContinuousPointContactConstraint::frictionStates(const Eigen::VectorXd& u,
                                                      std::vector<LinkState>& states) const {
  if (!friction()) {
    return;
  }
  std::vector<Eigen::Vector3d> force;
  std::vector<char> sliding;
  nodalFriction(u, statusAt(u), force, sliding);
  const Eigen::VectorXd du = u - uStart_;
  const std::array<const SparseRows*, 2> rows{&rows_.friction.T1, &rows_.friction.T2};
  for (std::size_t r = 0; r < states.size(); ++r) {
    const ContactLink& l = links_[static_cast<std::size_t>(rows_.link[r])];
    const int i = multiplierOfNode_[static_cast<std::size_t>(l.slave)];
    if (i < 0 || states[r].status == LinkStatus::Open) {
      continue;
    }
    const std::array<Point3, 2> t{l.tangent1, l.tangent2};
    for (std::size_t j = 0; j < 2; ++j) {
      const Eigen::Vector3d tj{t[j][0], t[j][1], t[j][2]};
      states[r].friction[j] = force[static_cast<std::size_t>(i)].dot(tj);
      if (rows[j]->rows() > static_cast<Eigen::Index>(r)) {
        states[r].slip[j] = rows[j]->row(static_cast<Eigen::Index>(r)).dot(du);
      }
    }
    states[r].status = sliding[static_cast<std::size_t>(i)] != 0 ? LinkStatus::Sliding : LinkStatus::Sticking;
  }
}

void ContinuousPointContactConstraint::acceptFrictionStep(const Eigen::VectorXd& u) {
  if (!friction()) {
    return;
  }
  const std::vector<char> status = statusAt(u);
  pressureT_.assign(points_.size(), Eigen::Vector2d::Zero());
  std::vector<Eigen::Vector3d> pressure(multiplierNode_.size(), Eigen::Vector3d::Zero());
  std::vector<double> weight(multiplierNode_.size(), 0.0);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    // on (t1, t2): B^T of the pressure along the friction directions (B orthonormal)
    pressureT_[q] = p.paired ? Eigen::Vector2d(p.basis.transpose() * tangentialPressureAt(q, status[q], u))
                             : Eigen::Vector2d::Zero();
    const Eigen::Vector2d pt = p.basis * pressureT_[q];
    const Eigen::Vector3d along = pt(0) * p.direction[0] + pt(1) * p.direction[1];
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      if (p.multiplier[k] >= 0) {
        pressure[static_cast<std::size_t>(p.multiplier[k])] += p.weight * p.shape[k] * along;
        weight[static_cast<std::size_t>(p.multiplier[k])] += p.weight * p.shape[k];
      }
    }
  }
  // LAGS_F: the tangential multiplier (STANDARD) or the nodal tangential pressure (PENALISATION), in
  // space, over the threshold mu |LAGS_C|; stored on the pairing's tangents of the node
  lagsFOut_.assign(multiplierNode_.size(), Eigen::Vector3d::Zero());
  const bool unknowns = frictionUnknowns();
  double mu = 0.0;
  for (const auto& z : definition_->zones) {
    mu = std::max(mu, z.resolve ? z.coulomb : 0.0);
  }
  std::vector<char> done(multiplierNode_.size(), 0);
  for (const ContactLink& l : links_) {
    const int i = multiplierOfNode_[static_cast<std::size_t>(l.slave)];
    if (i < 0 || !l.paired || done[static_cast<std::size_t>(i)] != 0) {
      continue;
    }
    const auto k = static_cast<std::size_t>(i);
    done[k] = 1;
    const Point3 n = l.normal;
    Point3 t1;
    Point3 t2;
    pointTangents(n, tangentComponents() == 2, t1, t2);
    const Eigen::Vector3d v = unknowns
                                  ? Eigen::Vector3d(lambdaT_[k](0) * Eigen::Vector3d(t1[0], t1[1], t1[2]) +
                                                    lambdaT_[k](1) * Eigen::Vector3d(t2[0], t2[1], t2[2]))
                                  : Eigen::Vector3d(weight[k] > 0.0 ? Eigen::Vector3d(pressure[k] / weight[k])
                                                                    : Eigen::Vector3d::Zero());
    const double limit = mu * std::max(0.0, -lambda_[k]);
    lagsFOut_[k] = limit > 0.0 ? Eigen::Vector3d(v / limit) : Eigen::Vector3d::Zero();
  }
}

void ContinuousPointContactConstraint::storeFriction(Field& out, std::size_t c0) const {
  const int nd = tangentComponents();
  for (std::size_t i = 0; i < multiplierNode_.size(); ++i) {
    const auto n = static_cast<std::size_t>(multiplierNode_[i]);
    for (int c = 0; c < nd; ++c) {
      out.value(n, c0 + static_cast<std::size_t>(c)) = 0.0;
      out.setDefined(n, c0 + static_cast<std::size_t>(c));
    }
  }
  for (const ContactLink& l : links_) {
    const int i = multiplierOfNode_[static_cast<std::size_t>(l.slave)];
    if (i < 0 || !l.paired || static_cast<std::size_t>(i) >= lagsFOut_.size()) {
      continue;
    }
    const Eigen::Vector3d& v = lagsFOut_[static_cast<std::size_t>(i)];
    const auto n = static_cast<std::size_t>(l.slave);
    const std::array<Point3, 2> t{l.tangent1, l.tangent2};
    for (int c = 0; c < nd; ++c) {
      const Point3& tc = t[static_cast<std::size_t>(c)];
      out.value(n, c0 + static_cast<std::size_t>(c)) = v(0) * tc[0] + v(1) * tc[1] + v(2) * tc[2];
    }
  }
}

} // namespace stella::contact
