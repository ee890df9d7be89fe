// The Coulomb law of a friction point of the continuous formulation (see the header).

#include "solver/contact/ContinuousCoulombLaw.hpp"
#include "messages/Messages.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace stella::contact {

Eigen::Vector2d coulombIndicator(const CoulombPoint& p, const Eigen::Vector2d& slip) {
  Eigen::Vector2d q = p.base + p.rho * slip;
  for (int j = p.directions; j < 2; ++j) {
    q(j) = 0.0; // no friction along an excluded direction
  }
  return q;
}

char coulombStatus(const CoulombPoint& p, const Eigen::Vector2d& slip) {
  if (p.directions == 0) {
    return 2; // friction excluded on every direction (SANS_GROUP_NO_FR): slides freely
  }
  // a zero threshold (no pressure yet) slides with no force, whatever the sign: a status from the
  // sign of a round-off slip would flip-flop
  const Eigen::Vector2d q = coulombIndicator(p, slip);
  if (q.norm() < p.limit) {
    return 1;
  }
  return p.senseInStatus && q(0) < 0.0 && p.limit > 0.0 ? 3 : 2;
}

Eigen::Vector2d coulombSlidingDirection(const CoulombPoint& p, char s, const Eigen::Vector2d& slip) {
  if (p.senseInStatus) {
    return {s == 3 ? -1.0 : 1.0, 0.0}; // the sense is the status's
  }
  const Eigen::Vector2d q = coulombIndicator(p, slip);
  const double size = q.norm();
  return size > 0.0 ? Eigen::Vector2d(q / size) : Eigen::Vector2d::Zero();
}

Eigen::Vector2d coulombPressure(const CoulombPoint& p, char s, const Eigen::Vector2d& slip) {
  if (s == 1) {
    return coulombIndicator(p, slip);
  }
  if (s != 2 && s != 3) {
    return Eigen::Vector2d::Zero();
  }
  return p.limit * coulombSlidingDirection(p, s, slip); // on the disc, along q / |q|
}

double frictionThresholdChange(const Eigen::VectorXd& before, const Eigen::VectorXd& now) {
  double change = 0.0;
  double scale = 0.0;
  for (Eigen::Index i = 0; i < now.size(); ++i) {
    scale = std::max(scale, now(i));
    if (i < before.size()) {
      change = std::max(change, std::fabs(now(i) - before(i)));
    }
  }
  if (scale > 0.0) {
    return change / scale;
  }
  return change > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

FrictionLoop frictionLoopStep(const ContinuousSettings& c, double criterion, int& iterations, double time,
                              const SourceLocation& at, const std::string& what, std::string& continuation) {
  // change <= RESI_FROT x max |LAGS_C| (none before the first correction)
  if (criterion < 0.0 || criterion <= c.frictionResidual) {
    return FrictionLoop::Accept;
  }
  if (!c.frictionFixedPoint) {
    // NEWTON: the threshold |LAGS_C| still moved at the last correction
    continuation = fmt::format("friction threshold moved by {:.2e} of |LAGS_C| (RESI_FROT {:g}): Newton "
                               "iterations go on",
                               criterion, c.frictionResidual);
    return FrictionLoop::NewtonGoesOn;
  }
  if (++iterations > c.maxFrictionIterations) {
    throw UserError(msg::make("CONTACT_28",
                              {{"time", time},
                               {"max_friction_iterations", c.maxFrictionIterations},
                               {"what", what},
                               {"criterion", criterion},
                               {"friction_residual", c.frictionResidual}},
                              at));
  }
  continuation = fmt::format("friction threshold updated (loop {}, change {:.2e} of |LAGS_C|): Newton "
                             "iterations go on",
                             iterations, criterion);
  return FrictionLoop::NewThreshold;
}

} // namespace stella::contact
