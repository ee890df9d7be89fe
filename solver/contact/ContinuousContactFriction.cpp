// Coulomb friction of the continuous formulation (FROTTEMENT='COULOMB', D_PLAN, C_PLAN, AXIS and 3D):
// the friction status, forces and loops of ContinuousContactConstraint (see its header). The
// friction directions of a row are the pairing's tangents (one in 2D and AXIS, two in 3D) or what
// SANS_GROUP_NO_FR / DIRE_EXCL_FROT leave of them (ContinuousFrictionOptions.cpp); the Coulomb
// cone is a disc: the indicator q (a vector of the tangent plane) against the threshold.

#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/ContinuousCoulombLaw.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace stella::contact {

namespace {

double frictionCoefficient(const ContinuousZone& z) {
  return z.frictionPenalised ? z.frictionPenalty : z.frictionAugmentation;
}

} // namespace

const ContinuousZone& ContinuousContactConstraint::zoneOfRow(Eigen::Index row) const {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  return definition_->zones[static_cast<std::size_t>(links_[k].zone)].continuous;
}

double ContinuousContactConstraint::coulombOfRow(Eigen::Index row) const {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  return definition_->zones[static_cast<std::size_t>(links_[k].zone)].coulomb;
}

int ContinuousContactConstraint::frictionDirections(Eigen::Index row) const {
  return friction() && static_cast<std::size_t>(row) < directions_.size()
             ? directions_[static_cast<std::size_t>(row)]
             : 0;
}

Eigen::MatrixXd ContinuousContactConstraint::slipsAt(const Eigen::VectorXd& u) const {
  // the relative tangential displacement of the slave node on the master since the step's start
  const auto m = static_cast<Eigen::Index>(rows_.link.size());
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(m, 2);
  const Eigen::VectorXd du = u - uStart_;
  for (int j = 0; j < 2; ++j) {
    if (frictionRow(j).rows() == m && m > 0) {
      s.col(j) = frictionRow(j) * du;
    }
  }
  return s;
}

double ContinuousContactConstraint::thresholdPressure(std::size_t k) const {
  if (definition_->settings.continuous.frictionFixedPoint) {
    return k < threshold_.size() ? threshold_[k] : 0.0;
  }
  return std::max(0.0, -lagsC_[k]);
}

CoulombPoint ContinuousContactConstraint::coulombPoint(Eigen::Index row) const {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  const ContinuousZone& z = zoneOfRow(row);
  CoulombPoint p;
  // STANDARD: the multiplier; PENALISATION: the tangential pressure at the start of the step (the
  // elastic predictor of the penalised stick: the spring keeps the force of the previous steps)
  p.base = z.frictionPenalised ? lagsFStart_[k] : lagsF_[k];
  p.rho = frictionCoefficient(z);
  p.limit = coulombOfRow(row) * thresholdPressure(k);
  p.directions = frictionDirections(row);
  p.senseInStatus = slidingSenseInStatus(row);
  return p;
}

Eigen::Vector2d ContinuousContactConstraint::indicator(Eigen::Index row, const Eigen::Vector2d& slip) const {
  return coulombIndicator(coulombPoint(row), slip);
}

char ContinuousContactConstraint::frictionStatus(Eigen::Index row, const Eigen::Vector2d& slip) const {
  return coulombStatus(coulombPoint(row), slip);
}

bool ContinuousContactConstraint::slidingSenseInStatus(Eigen::Index row) const {
  return frictionDirections(row) == 1 && definition_->settings.continuous.statusLoop != StatusLoop::Newton;
}

Eigen::Vector2d ContinuousContactConstraint::slidingDirection(Eigen::Index row, char s,
                                                              const Eigen::Vector2d& slip) const {
  return coulombSlidingDirection(coulombPoint(row), s, slip);
}

Eigen::Vector2d ContinuousContactConstraint::tangentialPressure(Eigen::Index row, char s,
                                                                const Eigen::Vector2d& slip) const {
  return coulombPressure(coulombPoint(row), s, slip);
}

// A sliding row's multiplier is a Newton unknown with the equation lambda_t = mu t e (the return
// map on the Coulomb disc, t the threshold pressure). Linearised with q = lambda_t + rho_t s and
// alpha = mu t / |q|: d(mu t e) = mu e dt + alpha P (dlambda_t + rho_t ds), P = I - e e^T; condensed
// with the equation's residual r = lambda_t - mu t e, the force's linearisation is
//   mu t e - beta P r + beta rho_t P ds + mu e dt,   beta = alpha / (1 - alpha) = mu t / (|q| - mu t),
// and the multiplier's update lambda_t + dlambda_t = mu (t + dt) e + beta P (rho_t ds - r). Without
// the condensation (the multiplier set to mu t e after each correction, a fixed point) a turning
// direction converges by a factor mu t / |q| per iteration (1 - 0.14 % with the default COEF_FROT).
// At the converged state r = 0 and the force is mu t e along the slip. |q| - mu t is floored at
// 1e-6 |q| (a node just sliding: a large but finite rotational stiffness).
ContinuousContactConstraint::SlidingNewton
ContinuousContactConstraint::slidingNewton(Eigen::Index row, char s, const Eigen::Vector2d& slip) const {
  SlidingNewton n;
  if (s != 2 || frictionDirections(row) != 2 || zoneOfRow(row).frictionPenalised) {
    return n;
  }
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  const double limit = coulombOfRow(row) * thresholdPressure(k);
  const Eigen::Vector2d q = indicator(row, slip);
  const double size = q.norm();
  if (!(limit > 0.0) || !(size > 0.0)) {
    return n;
  }
  n.active = true;
  n.e = q / size;
  n.beta = limit / std::max(size - limit, 1e-6 * size);
  n.r = lagsF_[k] - limit * n.e;
  return n;
}

std::vector<ContinuousContactConstraint::SlidingNewton>
ContinuousContactConstraint::slidingLinearisations(const Eigen::VectorXd& u,
                                                   const std::vector<char>& status) const {
  std::vector<SlidingNewton> out(rows_.link.size());
  if (!friction()) {
    return out;
  }
  const Eigen::MatrixXd slip = slipsAt(u);
  for (std::size_t i = 0; i < rows_.link.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    out[i] = slidingNewton(row, status[static_cast<std::size_t>(rows_.link[i])], slip.row(row).transpose());
  }
  return out;
}

void ContinuousContactConstraint::addFrictionForces(Eigen::Index row, char s, const Eigen::Vector2d& slip,
                                                    Eigen::VectorXd& forces,
                                                    std::vector<Eigen::Triplet<double>>* tangent,
                                                    const NodePosition* position,
                                                    const Eigen::VectorXd& u) const {
  const int d = frictionDirections(row);
  const double w = weight_(row);
  const SlidingNewton sliding = slidingNewton(row, s, slip);
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  if (s != 0) {
    p = tangentialPressure(row, s, slip);
    if (sliding.active) { // the condensed multiplier's equation: - beta P r
      p -= sliding.beta * (sliding.r - sliding.e * sliding.e.dot(sliding.r));
    }
    for (int j = 0; j < d; ++j) {
      for (SparseRows::InnerIterator it(frictionRow(j), row); it; ++it) {
        forces(it.col()) -= w * p(j) * it.value();
      }
    }
  }
  if (tangent == nullptr) {
    return;
  }
  // sticking: rho_t w T^T T; sliding: w beta rho_t T^T (I - e e^T) T, the turn of the direction
  // (zero in 2D; ALGO_FROT='PENALISATION': alpha = mu t / |q| instead of beta, the multiplier being
  // the step start's); its dependence on LAGS_C goes in the Schur complement; zeros keep the pattern
  const double rho = frictionCoefficient(zoneOfRow(row));
  Eigen::Matrix2d c = Eigen::Matrix2d::Zero();
  if (s == 1) {
    c = rho * w * Eigen::Matrix2d::Identity();
  } else if (s == 2 && d == 2) {
    const Eigen::Vector2d q = indicator(row, slip);
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
    const double limit = coulombOfRow(row) * thresholdPressure(k);
    const double size = q.norm();
    if (size > 0.0 && limit > 0.0) {
      const Eigen::Vector2d e = q / size;
      const double factor = sliding.active ? sliding.beta : limit / size;
      c = (w * factor * rho) * (Eigen::Matrix2d::Identity() - e * e.transpose());
    }
  }
  for (int a = 0; a < d; ++a) {
    for (int b = 0; b < d; ++b) {
      for (SparseRows::InnerIterator x(frictionRow(a), row); x; ++x) {
        for (SparseRows::InnerIterator y(frictionRow(b), row); y; ++y) {
          tangent->emplace_back(static_cast<int>(x.col()), static_cast<int>(y.col()),
                                c(a, b) * x.value() * y.value());
        }
      }
    }
  }
  if (position != nullptr) { // ALGO_RESO_GEOM='NEWTON': the variation of the rows
    addGeometricFrictionTangent(row, p, c, *position, u, *tangent);
  }
}

void ContinuousContactConstraint::updateSlidingPressures(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                                                         const std::vector<char>& status,
                                                         const std::vector<SlidingNewton>& newton) {
  if (!friction()) {
    return;
  }
  const Eigen::MatrixXd slip = slipsAt(u + ddu);
  const Eigen::Index m = static_cast<Eigen::Index>(rows_.link.size());
  for (std::size_t i = 0; i < rows_.link.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    if (status[k] < 2 || penalised(row)) { // 2 sliding, 3 sliding backwards (POINT_FIXE in 2D)
      continue;
    }
    const SlidingNewton& n = newton[i];
    if (!n.active) {
      // mu |lambda_n| q / |q| after the update, at the corrected displacement
      lagsF_[k] = tangentialPressure(row, status[k], slip.row(row).transpose());
      continue;
    }
    Eigen::Vector2d ds = Eigen::Vector2d::Zero(); // the correction's slip
    for (int j = 0; j < 2; ++j) {
      if (slipRow(j).rows() == m) {
        for (SparseRows::InnerIterator it(slipRow(j), row); it; ++it) {
          ds(j) += it.value() * ddu(it.col());
        }
      }
    }
    const double rho = frictionCoefficient(zoneOfRow(row));
    const Eigen::Vector2d v = rho * ds - n.r;
    lagsF_[k] = coulombOfRow(row) * thresholdPressure(k) * n.e + n.beta * (v - n.e * n.e.dot(v));
  }
}

void ContinuousContactConstraint::frictionState(Eigen::Index row, char s, const Eigen::Vector2d& slip,
                                                LinkState& state) const {
  const Eigen::Matrix2d& b = basis_[static_cast<std::size_t>(row)];
  const Eigen::Vector2d p = tangentialPressure(row, s, slip);
  const int d = frictionDirections(row);
  Eigen::Vector2d slipT = Eigen::Vector2d::Zero();
  Eigen::Vector2d forceT = Eigen::Vector2d::Zero();
  for (int j = 0; j < d; ++j) { // from the friction directions to the pairing's tangents
    slipT += slip(j) * b.row(j).transpose();
    forceT -= weight_(row) * p(j) * b.row(j).transpose();
  }
  state.slip = {slipT(0), slipT(1)};
  state.friction = {forceT(0), forceT(1)};
  state.status = s == 1 ? LinkStatus::Sticking : LinkStatus::Sliding;
}

void ContinuousContactConstraint::acceptFrictionState(Eigen::Index row, const LinkState& state) {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  const double w = weight_(row);
  const Eigen::Matrix2d& b = basis_[static_cast<std::size_t>(row)];
  const Eigen::Vector2d f{state.friction[0], state.friction[1]};
  lagsF_[k].setZero();
  for (int j = 0; j < frictionDirections(row) && w > 0.0; ++j) {
    lagsF_[k](j) = -b.row(j).dot(f) / w;
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

double ContinuousContactConstraint::frictionCriterion() const {
  const auto& c = definition_->settings.continuous;
  const std::vector<double>& before = c.frictionFixedPoint ? threshold_ : lastThreshold_;
  if (before.empty()) {
    return -1.0;
  }
  const auto m = static_cast<Eigen::Index>(rows_.link.size());
  Eigen::VectorXd was = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd now(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    now(i) = std::max(0.0, -lagsC_[k]);
    was(i) = k < before.size() ? before[k] : now(i);
  }
  return frictionThresholdChange(was, now);
}

bool ContinuousContactConstraint::acceptFriction(const Eigen::VectorXd& u) {
  const FrictionLoop step =
      frictionLoopStep(definition_->settings.continuous, frictionCriterion(), frictionIterations_, time_,
                       definition_->location, "", continuation_);
  if (step != FrictionLoop::NewThreshold) {
    return step == FrictionLoop::Accept;
  }
  for (std::size_t i = 0; i < rows_.link.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    threshold_[k] = std::max(0.0, -lagsC_[k]);
  }
  status_ = statusAt(u); // the stick/slip status under the new threshold
  lastStatus_ = status_;
  return false;
}

} // namespace stella::contact
