// Coulomb friction of LAC contact (FROTTEMENT='COULOMB' with ALGO_CONT='LAC', 2D and 3D models;
// beyond code_aster, whose LAC solves frictionless contact only): one tangential pressure vector
// lambda_t,P per patch (its components along tau, n_s turned by +90 degrees, in 2D; along tau_1,
// tau_2 in 3D: LacPairing.hpp), the mortar slip s_P,a = dS_P,a . (u - u_start) / L_P (the relative
// tangential displacement integrated over the overlaps), the augmented Lagrangian of the
// continuous formulation with the patch as the contact point (ContinuousContactConstraint.hpp):
// indicator q = lambda_t + rho_t s_P, threshold mu |lambda_P| (the current LAGS_C; the Coulomb
// disc, an interval in 2D); stick (|q| < threshold): the rows s_P,a = 0 in the Schur complement
// and the force -q . dS_P (tangent rho_t / L_P sum_a dS_a dS_a^T); slip: the force
// -mu |lambda_P| q/|q| . dS_P, whose dependence on lambda_P goes into the pressure's column of the
// Schur complement (LacSchur.cpp: non-symmetric, LU) and whose turning direction into the tangent
// (3D). RESI_FROT bounds the change of the threshold made by the last correction (relative to the
// largest threshold) for a step to end.

#include "solver/contact/lac/LacContactConstraint.hpp"

#include "solver/database/Result.hpp"

#include <algorithm>
#include <cmath>

namespace stella::contact::lac {

LacContactConstraint::Tangential LacContactConstraint::slipAt(std::size_t p, const Eigen::VectorXd& u) const {
  const LacPatchRow& r = rows_[p];
  Tangential s{0.0, 0.0};
  for (std::size_t a = 0; a < directions() && a < r.slipGradients.size(); ++a) {
    for (const auto& [e, v] : r.slipGradients[a]) {
      s[a] += v * (u(e) - uStart_(e));
    }
    s[a] /= r.pairedLength;
  }
  return s;
}

LacContactConstraint::Tangential LacContactConstraint::indicator(std::size_t p,
                                                                 const Eigen::VectorXd& u) const {
  const Tangential s = slipAt(p, u);
  return {lagsT_[p][0] + rhoT_ * s[0], lagsT_[p][1] + rhoT_ * s[1]};
}

namespace {

double length(const std::array<double, 2>& q) {
  return std::hypot(q[0], q[1]);
}

} // namespace

double LacContactConstraint::frictionLimit(std::size_t p) const {
  const double mu = definition_->zones[static_cast<std::size_t>(patchZone_[p])].coulomb;
  return mu * std::max(0.0, -lagsC_[p]);
}

char LacContactConstraint::contactCode(std::size_t p, const Eigen::VectorXd& u) const {
  if (!friction()) {
    return 1;
  }
  return length(indicator(p, u)) < frictionLimit(p) ? 1 : 2; // a zero threshold slides with no force
}

LacContactConstraint::Tangential LacContactConstraint::tangentialPressure(std::size_t p, char s,
                                                                          const Eigen::VectorXd& u) const {
  const Tangential q = indicator(p, u);
  if (s == 1) {
    return q;
  }
  const double size = length(q);
  if (s != 2 || size == 0.0) {
    return {0.0, 0.0};
  }
  const double limit = frictionLimit(p);
  return {limit * q[0] / size, limit * q[1] / size}; // on the Coulomb disc, along q
}

LacContactConstraint::Tangential LacContactConstraint::slidingCoupling(std::size_t p,
                                                                       const Eigen::VectorXd& u) const {
  if (!friction() || lastStatus_.size() != rows_.size() || lastStatus_[p] != 2) {
    return {0.0, 0.0};
  }
  const Tangential q = indicator(p, u);
  const double size = length(q);
  if (size == 0.0) {
    return {0.0, 0.0};
  }
  const double mu = definition_->zones[static_cast<std::size_t>(patchZone_[p])].coulomb;
  return {-mu * q[0] / size, -mu * q[1] / size};
}

// A sliding patch's tangential multiplier is a Newton unknown (3D) with the equation
// lambda_t = mu t e (the return map on the Coulomb disc, t = |LAGS_C|, e = q / |q|), condensed as
// the continuous formulation's (ContinuousContactFriction.cpp, slidingNewton): with
// beta = mu t / (|q| - mu t), P = I - e e^T and the residual r = lambda_t - mu t e, the force's
// pressure is mu t e - beta P r, its tangent beta rho_t / L P (the turn of the direction), and after
// a correction lambda_t = mu (t + dt) e + beta P (rho_t ds - r) (ds the correction's mean slip).
// Without it (the multiplier put back on the disc along q after each correction, a fixed point) a
// turning direction converged by a factor 1 - rho_t |ds| / (mu t) per iteration: lac_friction_3d_turn
// did not converge. |q| - mu t is floored at 1e-6 |q|. In 2D the direction cannot turn: inactive.
LacContactConstraint::SlidingNewton LacContactConstraint::slidingNewton(std::size_t p, char s,
                                                                        const Eigen::VectorXd& u) const {
  SlidingNewton n;
  if (s != 2 || directions() != 2) {
    return n;
  }
  const double limit = frictionLimit(p);
  const Tangential q = indicator(p, u);
  const double size = length(q);
  if (!(limit > 0.0) || !(size > 0.0)) {
    return n;
  }
  n.active = true;
  n.e = {q[0] / size, q[1] / size};
  n.beta = limit / std::max(size - limit, 1e-6 * size);
  n.r = {lagsT_[p][0] - limit * n.e[0], lagsT_[p][1] - limit * n.e[1]};
  return n;
}

void LacContactConstraint::updateSlidingPressures(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                                                  const std::vector<char>& status,
                                                  const std::vector<SlidingNewton>& newton) {
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    if (status[p] != 2) {
      continue;
    }
    const SlidingNewton& n = newton[p];
    if (!n.active) {
      lagsT_[p] = tangentialPressure(p, 2, u); // on the threshold of the corrected LAGS_C
      continue;
    }
    const LacPatchRow& r = rows_[p];
    Tangential v{0.0, 0.0}; // rho_t ds - r
    for (std::size_t a = 0; a < 2; ++a) {
      double ds = 0.0;
      for (const auto& [e, g] : r.slipGradients[a]) {
        ds += g * ddu(e);
      }
      v[a] = rhoT_ * ds / r.pairedLength - n.r[a];
    }
    const double along = n.e[0] * v[0] + n.e[1] * v[1];
    const double limit = frictionLimit(p);
    for (std::size_t a = 0; a < 2; ++a) {
      lagsT_[p][a] = limit * n.e[a] + n.beta * (v[a] - n.e[a] * along);
    }
  }
}

// Forces -sum_a t_a dS_a. Tangent: sticking, rho_t / L sum_a dS_a dS_a^T; sliding, the turning of
// the direction q/|q| on the disc, beta rho_t / L sum_ab (delta_ab - qhat_a qhat_b) dS_a dS_b^T
// (zero in 2D, where the direction cannot turn). Every (a, b) pair is written, zeros
// included, so that the pattern does not depend on the statuses.
void LacContactConstraint::addFrictionForces(std::size_t p, char s, const Eigen::VectorXd& u,
                                             Eigen::VectorXd& forces,
                                             std::vector<Eigen::Triplet<double>>* tangent) const {
  const LacPatchRow& r = rows_[p];
  const std::size_t nd = std::min(directions(), r.slipGradients.size());
  const SlidingNewton sliding = slidingNewton(p, s, u);
  if (s != 0) {
    Tangential t = tangentialPressure(p, s, u);
    if (sliding.active) { // the condensed multiplier's equation: - beta P r
      const double along = sliding.e[0] * sliding.r[0] + sliding.e[1] * sliding.r[1];
      for (std::size_t a = 0; a < 2; ++a) {
        t[a] -= sliding.beta * (sliding.r[a] - sliding.e[a] * along);
      }
    }
    for (std::size_t a = 0; a < nd; ++a) {
      for (const auto& [e, v] : r.slipGradients[a]) {
        forces(e) -= t[a] * v;
      }
    }
  }
  if (tangent == nullptr) {
    return;
  }
  double c[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  if (s == 1) {
    c[0][0] = c[1][1] = rhoT_ / r.pairedLength;
  } else if (s == 2 && nd == 2) {
    const Tangential q = indicator(p, u);
    const double size = length(q);
    if (size > 0.0) {
      const double factor = sliding.active ? sliding.beta : frictionLimit(p) / size;
      const double k = factor * rhoT_ / r.pairedLength;
      const double h[2] = {q[0] / size, q[1] / size};
      for (std::size_t a = 0; a < 2; ++a) {
        for (std::size_t b = 0; b < 2; ++b) {
          c[a][b] = k * ((a == b ? 1.0 : 0.0) - h[a] * h[b]);
        }
      }
    }
  }
  for (std::size_t a = 0; a < nd; ++a) {
    for (std::size_t b = 0; b < nd; ++b) {
      for (const auto& [i, vi] : r.slipGradients[a]) {
        for (const auto& [j, vj] : r.slipGradients[b]) {
          tangent->emplace_back(i, j, c[a][b] * vi * vj);
        }
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
  // LAGS_F1 (LAGS_F2 in 3D): the tangential pressure along tau_a over the Coulomb threshold
  // mu |LAGS_C| (norm <= 1, 1 sliding)
  for (std::size_t p = 0; p < patchNode_.size(); ++p) {
    if (patchNode_[p] < 0) {
      continue;
    }
    const double limit = frictionLimit(p);
    const auto n = static_cast<std::size_t>(patchNode_[p]);
    for (std::size_t a = 0; a < directions(); ++a) {
      out.value(n, c0 + a) = limit > 0.0 ? lagsT_[p][a] / limit : 0.0;
      out.setDefined(n, c0 + a);
    }
  }
}

} // namespace stella::contact::lac
