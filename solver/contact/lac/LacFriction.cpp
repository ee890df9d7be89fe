// Coulomb friction of LAC contact (FROTTEMENT='COULOMB' with ALGO_CONT='LAC', 2D models; beyond
// code_aster, whose LAC solves frictionless contact only): one tangential pressure lambda_t,P per
// patch (along tau = n_s turned by +90 degrees), the mortar slip s_P = dS_P . (u - u_start) / L_P
// (LacPairing.hpp: the relative tangential displacement integrated over the overlaps), the
// augmented Lagrangian of the continuous formulation with the patch as the contact point
// (ContinuousContactConstraint.hpp): indicator q = lambda_t + rho_t s_P, threshold mu |lambda_P|
// (the current LAGS_C, the Coulomb disc of 2D is an interval); stick (|q| < threshold): the row
// s_P = 0 in the Schur complement and the force -q dS_P (tangent rho_t / L_P dS dS^T); slip: the
// force -mu |lambda_P| sign(q) dS_P, whose dependence on lambda_P goes into the pressure's column of
// the Schur complement (LacSchur.cpp: non-symmetric, LU). RESI_FROT bounds the change of the
// threshold made by the last correction (relative to the largest threshold) for a step to end.

#include "solver/contact/lac/LacContactConstraint.hpp"

#include "solver/database/Result.hpp"

#include <algorithm>
#include <cmath>

namespace stella::contact::lac {

double LacContactConstraint::slipAt(std::size_t p, const Eigen::VectorXd& u) const {
  const LacPatchRow& r = rows_[p];
  double s = 0.0;
  for (const auto& [e, v] : r.slipGradient) {
    s += v * (u(e) - uStart_(e));
  }
  return s / r.pairedLength;
}

double LacContactConstraint::frictionLimit(std::size_t p) const {
  const double mu = definition_->zones[static_cast<std::size_t>(patchZone_[p])].coulomb;
  return mu * std::max(0.0, -lagsC_[p]);
}

char LacContactConstraint::contactCode(std::size_t p, const Eigen::VectorXd& u) const {
  if (!friction()) {
    return 1;
  }
  const double q = lagsT_[p] + rhoT_ * slipAt(p, u);
  return std::fabs(q) < frictionLimit(p) ? 1 : 2; // a zero threshold slides with no force
}

double LacContactConstraint::tangentialPressure(std::size_t p, char s, const Eigen::VectorXd& u) const {
  const double q = lagsT_[p] + rhoT_ * slipAt(p, u);
  if (s == 1) {
    return q;
  }
  if (s != 2 || q == 0.0) {
    return 0.0;
  }
  return q > 0.0 ? frictionLimit(p) : -frictionLimit(p);
}

double LacContactConstraint::slidingCoupling(std::size_t p, const Eigen::VectorXd& u) const {
  if (!friction() || lastStatus_.size() != rows_.size() || lastStatus_[p] != 2) {
    return 0.0;
  }
  const double q = lagsT_[p] + rhoT_ * slipAt(p, u);
  const double mu = definition_->zones[static_cast<std::size_t>(patchZone_[p])].coulomb;
  return q > 0.0 ? -mu : q < 0.0 ? mu : 0.0;
}

void LacContactConstraint::addFrictionForces(std::size_t p, char s, const Eigen::VectorXd& u,
                                             Eigen::VectorXd& forces,
                                             std::vector<Eigen::Triplet<double>>* tangent) const {
  const LacPatchRow& r = rows_[p];
  if (s != 0) {
    const double t = tangentialPressure(p, s, u);
    for (const auto& [e, v] : r.slipGradient) {
      forces(e) -= t * v;
    }
  }
  if (tangent != nullptr) {
    const double c = s == 1 ? rhoT_ / r.pairedLength : 0.0; // zeros keep the pattern
    for (const auto& [i, vi] : r.slipGradient) {
      for (const auto& [j, vj] : r.slipGradient) {
        tangent->emplace_back(i, j, c * vi * vj);
      }
    }
  }
}

bool LacContactConstraint::frictionSettled() {
  if (!friction() || limitAfter_.size() != limitBefore_.size()) {
    return true;
  }
  double change = 0.0;
  double largest = 0.0;
  for (std::size_t p = 0; p < limitAfter_.size(); ++p) {
    change = std::max(change, std::fabs(limitAfter_[p] - limitBefore_[p]));
    largest = std::max(largest, limitAfter_[p]);
  }
  if (!(change > definition_->settings.continuous.frictionResidual * largest)) {
    return true;
  }
  limitBefore_ = limitAfter_; // the next correction's change is measured from here
  continuation_ =
      "friction threshold of the LAC patches moved by more than RESI_FROT: Newton iterations go on";
  return false;
}

void LacContactConstraint::storeFriction(Field& out, std::size_t c0) const {
  // LAGS_F1: the tangential pressure over the Coulomb threshold mu |LAGS_C| (|.| <= 1, 1 sliding)
  for (std::size_t p = 0; p < patchNode_.size(); ++p) {
    if (patchNode_[p] < 0) {
      continue;
    }
    const double limit = frictionLimit(p);
    const auto n = static_cast<std::size_t>(patchNode_[p]);
    out.value(n, c0) = limit > 0.0 ? lagsT_[p] / limit : 0.0;
    out.setDefined(n, c0);
  }
}

} // namespace stella::contact::lac
