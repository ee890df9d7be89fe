// Coulomb friction of the continuous contact at integration points (ContinuousPointContact.hpp): the
// law of ContinuousCoulombLaw at each point, the tangential multipliers on the slave nodes, the
// friction loop and the friction fields.

#include "solver/contact/ContinuousPointContact.hpp"

#include "solver/contact/ContactResultField.hpp"
#include "solver/database/Result.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella::contact {

bool ContinuousPointContactConstraint::frictionUnknowns() const {
  if (!friction()) {
    return false;
  }
  for (const auto& z : definition_->zones) {
    if (z.resolve && !z.continuous.frictionPenalised) {
      return true;
    }
  }
  return false;
}

double ContinuousPointContactConstraint::coulombOf(const ContactPoint& p) const {
  return definition_->zones[static_cast<std::size_t>(p.zone)].coulomb;
}

double ContinuousPointContactConstraint::thresholdAt(std::size_t q) const {
  if (definition_->settings.continuous.frictionFixedPoint) {
    return q < threshold_.size() ? threshold_[q] : 0.0;
  }
  return std::max(0.0, -lambdaAt(points_[q]));
}

Eigen::Vector2d ContinuousPointContactConstraint::slipAt(const ContactPoint& p,
                                                         const Eigen::VectorXd& u) const {
  double s = 0.0;
  for (const auto& [e, a] : p.tangentRow) {
    s += a * (u(e) - uStart_(e));
  }
  return {s, 0.0};
}

double ContinuousPointContactConstraint::lambdaTAt(const ContactPoint& p) const {
  double l = 0.0;
  for (std::size_t k = 0; k < p.nodes.size(); ++k) {
    if (p.multiplier[k] >= 0) {
      l += p.shape[k] * lambdaT_[static_cast<std::size_t>(p.multiplier[k])];
    }
  }
  return l;
}

CoulombPoint ContinuousPointContactConstraint::coulombAt(std::size_t q) const {
  const ContactPoint& p = points_[q];
  const ContinuousZone& z = definition_->zones[static_cast<std::size_t>(p.zone)].continuous;
  CoulombPoint c;
  c.base = {z.frictionPenalised ? pressureTStart_[q] : lambdaTAt(p), 0.0};
  c.rho = z.frictionPenalised ? z.frictionPenalty : z.frictionAugmentation;
  c.limit = coulombOf(p) * thresholdAt(q);
  c.directions = 1;
  c.senseInStatus = definition_->settings.continuous.statusLoop != StatusLoop::Newton;
  return c;
}

double ContinuousPointContactConstraint::tangentialPressureAt(std::size_t q, char s,
                                                              const Eigen::VectorXd& u) const {
  return s == 0 ? 0.0 : coulombPressure(coulombAt(q), s, slipAt(points_[q], u))(0);
}

void ContinuousPointContactConstraint::addFrictionForces(std::size_t q, char s, const Eigen::VectorXd& u,
                                                         Eigen::VectorXd& forces,
                                                         std::vector<Eigen::Triplet<double>>* tangent) const {
  const ContactPoint& p = points_[q];
  const double pt = tangentialPressureAt(q, s, u);
  for (const auto& [e, a] : p.tangentRow) {
    forces(e) -= p.weight * pt * a;
  }
  if (tangent == nullptr) {
    return;
  }
  // sticking: rho_t w T^T T (sliding in 2D: no tangent of the direction; its dependence on LAGS_C
  // goes in the multipliers' system); zeros keep the pattern
  const double c = s == 1 ? coulombAt(q).rho * p.weight : 0.0;
  for (const auto& [e, a] : p.tangentRow) {
    for (const auto& [f, b] : p.tangentRow) {
      tangent->emplace_back(e, f, c * a * b);
    }
  }
}

void ContinuousPointContactConstraint::frictionEquations(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                                                         const std::vector<char>& status,
                                                         MultiplierSystem& sys) const {
  if (!friction()) {
    return;
  }
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  const bool newton = newtonFriction();
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (!p.paired || p.weight == 0.0 || p.penalised) {
      continue;
    }
    const CoulombPoint c = coulombAt(q);
    const bool unknowns = frictionUnknowns() &&
                          !definition_->zones[static_cast<std::size_t>(p.zone)].continuous.frictionPenalised;
    if (status[q] == 0) {
      if (unknowns) { // out of contact: lambda_t,p = 0 (weakly), as LAGS_C's equation of an open point
        addTangentialMass(p, c.rho, 0.0, sys);
      }
      continue;
    }
    const Eigen::Vector2d slip = slipAt(p, u);
    const double mu = coulombOf(p);
    const bool sliding = status[q] >= 2;
    const double e = sliding ? coulombSlidingDirection(c, status[q], slip)(0) : 0.0;
    // NEWTON: the sliding force -w mu t_p e T_p with t_p = -lambda_p follows LAGS_C
    const bool coupled = newton && sliding && lambdaAt(p) < 0.0 && e != 0.0;
    if (coupled) {
      sys.symmetric = false;
      for (std::size_t k = 0; k < p.nodes.size(); ++k) {
        const int i = p.multiplier[k];
        if (i >= 0 && p.shape[k] != 0.0) {
          for (const auto& [dof, a] : p.tangentRow) {
            sys.column[static_cast<std::size_t>(i)].emplace_back(dof, -p.weight * mu * e * p.shape[k] * a);
          }
        }
      }
    }
    if (!unknowns) {
      continue;
    }
    double tdu = 0.0;
    for (const auto& [dof, a] : p.tangentRow) {
      tdu += a * ddu(dof);
    }
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const int i = p.multiplier[k];
      if (i < 0 || p.shape[k] == 0.0) {
        continue;
      }
      const Eigen::Index ti = nm + i;
      const double wn = p.weight * p.shape[k];
      sys.used[static_cast<std::size_t>(ti)] = 1;
      if (!sliding) { // the slip vanishes (weakly)
        for (const auto& [dof, a] : p.tangentRow) {
          sys.row[static_cast<std::size_t>(ti)].emplace_back(dof, wn * a);
        }
        sys.residual(ti) += wn * (slip(0) + tdu);
        continue;
      }
      // the multiplier is the sliding pressure mu t_p e (weakly; addTangentialMass below), whose
      // threshold follows LAGS_C with NEWTON
      for (std::size_t l = 0; l < p.nodes.size() && coupled; ++l) {
        const int j = p.multiplier[l];
        if (j >= 0) {
          sys.mass(ti, j) += wn * p.shape[l] * mu * e / c.rho; // -d(mu t_p e)/dlambda_j / rho_t
        }
      }
    }
    if (sliding) {
      addTangentialMass(p, c.rho, c.limit * e, sys);
    }
  }
}

void ContinuousPointContactConstraint::addTangentialMass(const ContactPoint& p, double rho, double target,
                                                         MultiplierSystem& sys) const {
  // (1/rho_t) w N_i (target - lambda_t,p) in the residual, M = (1/rho_t) w N N^T
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  const double lt = lambdaTAt(p);
  for (std::size_t k = 0; k < p.nodes.size(); ++k) {
    const int i = p.multiplier[k];
    if (i < 0) {
      continue;
    }
    const double wn = p.weight * p.shape[k];
    sys.residual(nm + i) += wn / rho * (target - lt);
    for (std::size_t l = 0; l < p.nodes.size(); ++l) {
      const int j = p.multiplier[l];
      if (j >= 0) {
        sys.mass(nm + i, nm + j) += wn * p.shape[l] / rho;
      }
    }
  }
}

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
    const double pt = tangentialPressureAt(q, status[q], u);
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const int i = p.multiplier[k];
      if (i >= 0 && p.shape[k] != 0.0) {
        force[static_cast<std::size_t>(i)] -= p.weight * p.shape[k] * pt * p.tangent;
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
  const SparseRows& t1 = rows_.friction.T1;
  for (std::size_t r = 0; r < states.size(); ++r) {
    const ContactLink& l = links_[static_cast<std::size_t>(rows_.link[r])];
    const int i = multiplierOfNode_[static_cast<std::size_t>(l.slave)];
    if (i < 0 || states[r].status == LinkStatus::Open) {
      continue;
    }
    const Eigen::Vector3d t{l.tangent1[0], l.tangent1[1], l.tangent1[2]};
    states[r].friction = {force[static_cast<std::size_t>(i)].dot(t), 0.0};
    if (t1.rows() > static_cast<Eigen::Index>(r)) {
      states[r].slip = {t1.row(static_cast<Eigen::Index>(r)).dot(du), 0.0};
    }
    states[r].status = sliding[static_cast<std::size_t>(i)] != 0 ? LinkStatus::Sliding : LinkStatus::Sticking;
  }
}

void ContinuousPointContactConstraint::acceptFrictionStep(const Eigen::VectorXd& u) {
  if (!friction()) {
    return;
  }
  const std::vector<char> status = statusAt(u);
  pressureT_.assign(points_.size(), 0.0);
  std::vector<double> pressure(multiplierNode_.size(), 0.0);
  std::vector<double> weight(multiplierNode_.size(), 0.0);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    pressureT_[q] = p.paired ? tangentialPressureAt(q, status[q], u) : 0.0;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      if (p.multiplier[k] >= 0) {
        pressure[static_cast<std::size_t>(p.multiplier[k])] += p.weight * p.shape[k] * pressureT_[q];
        weight[static_cast<std::size_t>(p.multiplier[k])] += p.weight * p.shape[k];
      }
    }
  }
  // LAGS_F1: the tangential multiplier (STANDARD) or the nodal tangential pressure (PENALISATION),
  // over the threshold mu |LAGS_C|
  lagsFOut_.assign(multiplierNode_.size(), 0.0);
  const bool unknowns = frictionUnknowns();
  for (std::size_t i = 0; i < multiplierNode_.size(); ++i) {
    const double pt = unknowns ? lambdaT_[i] : (weight[i] > 0.0 ? pressure[i] / weight[i] : 0.0);
    double mu = 0.0;
    for (const auto& z : definition_->zones) {
      mu = std::max(mu, z.resolve ? z.coulomb : 0.0);
    }
    const double limit = mu * std::max(0.0, -lambda_[i]);
    lagsFOut_[i] = limit > 0.0 ? pt / limit : 0.0;
  }
  // on the pairing's tangent of the node (as the nodal formulation's LAGS_F1): the points' t is the
  // master normal turned by +90 degrees
  for (const ContactLink& l : links_) {
    const int i = multiplierOfNode_[static_cast<std::size_t>(l.slave)];
    if (i >= 0 && l.paired) {
      const double sense = -l.normal[1] * l.tangent1[0] + l.normal[0] * l.tangent1[1];
      lagsFOut_[static_cast<std::size_t>(i)] *= sense < 0.0 ? -1.0 : 1.0;
    }
  }
}

void ContinuousPointContactConstraint::storeFriction(Field& out, std::size_t c0) const {
  for (std::size_t i = 0; i < multiplierNode_.size(); ++i) {
    const auto n = static_cast<std::size_t>(multiplierNode_[i]);
    out.value(n, c0) = i < lagsFOut_.size() ? lagsFOut_[i] : 0.0;
    out.setDefined(n, c0);
  }
}

} // namespace stella::contact
