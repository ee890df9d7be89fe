// Coulomb friction of the continuous formulation (FROTTEMENT='COULOMB', D_PLAN and C_PLAN): the
// friction status, forces and loops of ContinuousContactConstraint (see its header).

#include "solver/contact/ContinuousContactConstraint.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella::contact {

namespace {

double frictionCoefficient(const ContinuousZone& z) {
  return z.frictionPenalised ? z.frictionPenalty : z.frictionAugmentation;
}

} // namespace

double ContinuousContactConstraint::trialBase(std::size_t k, const ContinuousZone& z) const {
  // STANDARD: the multiplier; PENALISATION: the tangential pressure at the start of the step (the
  // elastic predictor of the penalised stick: the spring keeps the force of the previous steps)
  return z.frictionPenalised ? (k < lagsFStart_.size() ? lagsFStart_[k] : 0.0) : lagsF_[k];
}

const ContinuousZone& ContinuousContactConstraint::zoneOfRow(Eigen::Index row) const {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  return definition_->zones[static_cast<std::size_t>(links_[k].zone)].continuous;
}

double ContinuousContactConstraint::coulombOfRow(Eigen::Index row) const {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  return definition_->zones[static_cast<std::size_t>(links_[k].zone)].coulomb;
}

Eigen::VectorXd ContinuousContactConstraint::slipsAt(const Eigen::VectorXd& u) const {
  // the relative tangential displacement of the slave node on the master since the step's start
  return rows_.friction.T1 * (u - uStart_);
}

double ContinuousContactConstraint::thresholdPressure(std::size_t k) const {
  if (definition_->settings.continuous.frictionFixedPoint) {
    return k < threshold_.size() ? threshold_[k] : 0.0;
  }
  return std::max(0.0, -lagsC_[k]);
}

char ContinuousContactConstraint::frictionStatus(Eigen::Index row, double slip) const {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  const ContinuousZone& z = zoneOfRow(row);
  const double q = trialBase(k, z) + frictionCoefficient(z) * slip;
  const double limit = coulombOfRow(row) * thresholdPressure(k);
  if (std::fabs(q) < limit) {
    return 1;
  }
  // a zero threshold (no pressure yet) slides with no force, whatever the direction: a status
  // from the sign of a round-off slip would flip-flop
  return q >= 0.0 || limit <= 0.0 ? 2 : 3;
}

double ContinuousContactConstraint::tangentialPressure(Eigen::Index row, char s, double slip) const {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  const ContinuousZone& z = zoneOfRow(row);
  switch (s) {
  case 1:
    return trialBase(k, z) + frictionCoefficient(z) * slip;
  case 2:
    return coulombOfRow(row) * thresholdPressure(k);
  case 3:
    return -coulombOfRow(row) * thresholdPressure(k);
  default:
    return 0.0;
  }
}

void ContinuousContactConstraint::addFrictionForces(Eigen::Index row, char s, double slip,
                                                    Eigen::VectorXd& forces,
                                                    std::vector<Eigen::Triplet<double>>* tangent) const {
  const SparseRows& t1 = rows_.friction.T1;
  const double w = weight_(row);
  if (s != 0) {
    const double p = tangentialPressure(row, s, slip);
    for (SparseRows::InnerIterator it(t1, row); it; ++it) {
      forces(it.col()) -= w * p * it.value();
    }
  }
  if (tangent != nullptr) {
    // sticking: rho_t w T1^T T1; sliding: the force does not depend on u (its dependence on
    // LAGS_C goes in the Schur complement); zeros keep the pattern
    const double c = s == 1 ? frictionCoefficient(zoneOfRow(row)) * w : 0.0;
    for (SparseRows::InnerIterator p(t1, row); p; ++p) {
      for (SparseRows::InnerIterator q(t1, row); q; ++q) {
        tangent->emplace_back(static_cast<int>(p.col()), static_cast<int>(q.col()),
                              c * p.value() * q.value());
      }
    }
  }
}

void ContinuousContactConstraint::resetFrictionStep() {
  if (!friction()) {
    return;
  }
  threshold_.assign(links_.size(), 0.0);
  for (std::size_t k = 0; k < links_.size() && k < lagsC_.size(); ++k) {
    threshold_[k] = std::max(0.0, -lagsC_[k]); // the pressure at the start of the step
  }
  frictionIterations_ = 0;
  lastThreshold_.clear();
}

void ContinuousContactConstraint::recordThreshold() {
  if (!friction()) {
    return;
  }
  lastThreshold_.assign(links_.size(), 0.0);
  for (std::size_t k = 0; k < links_.size(); ++k) {
    lastThreshold_[k] = std::max(0.0, -lagsC_[k]);
  }
}

bool ContinuousContactConstraint::acceptFriction(const Eigen::VectorXd& u) {
  const auto& c = definition_->settings.continuous;
  const std::vector<double>& before = c.frictionFixedPoint ? threshold_ : lastThreshold_;
  double change = 0.0;
  double scale = 0.0;
  for (std::size_t i = 0; i < rows_.link.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    const double now = std::max(0.0, -lagsC_[k]);
    scale = std::max(scale, now);
    if (k < before.size()) {
      change = std::max(change, std::fabs(now - before[k]));
    }
  }
  if (before.empty() || change <= c.frictionResidual * scale) {
    return true;
  }
  if (!c.frictionFixedPoint) {
    // NEWTON: the threshold |LAGS_C| still moved at the last correction
    continuation_ = fmt::format("friction threshold moved by {:.2e} of |LAGS_C| (RESI_FROT {:g}): Newton "
                                "iterations go on",
                                change / scale, c.frictionResidual);
    return false;
  }
  if (++frictionIterations_ > c.maxFrictionIterations) {
    throw UserError(
        Diagnostic::noConvergence(
            "CONTACT_28",
            fmt::format(
                "the friction loop (ALGO_RESO_FROT='POINT_FIXE') did not converge at INST {}: after {} "
                "friction iterations the threshold |LAGS_C| still changes by {:.2e} of its maximum "
                "(RESI_FROT {:g})",
                time_, c.maxFrictionIterations, change / scale, c.frictionResidual),
            definition_->location)
            .withNote("raise ITER_FROT_MAXI, use ALGO_RESO_FROT='NEWTON', or refine the list of instants"));
  }
  for (std::size_t i = 0; i < rows_.link.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    threshold_[k] = std::max(0.0, -lagsC_[k]);
  }
  status_ = statusAt(u); // the stick/slip status under the new threshold
  lastStatus_ = status_;
  continuation_ = fmt::format("friction threshold updated (loop {}, change {:.2e} of |LAGS_C|): Newton "
                              "iterations go on",
                              frictionIterations_, change / scale);
  return false;
}

} // namespace stella::contact
