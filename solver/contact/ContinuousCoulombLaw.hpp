#pragma once
// The Coulomb law of the continuous formulation at one friction point (a slave node of
// ContinuousContactConstraint, or a contact point of ContinuousPointContactConstraint), shared by
// both: the cone is a disc of the tangent plane (one or two friction directions), the indicator
//   q = base + rho_t s
// (ALGO_FROT='STANDARD': base = the tangential multiplier, rho_t = COEF_FROT; 'PENALISATION': base
// = the tangential pressure at the start of the step, rho_t = COEF_PENA_FROT: the return mapping
// of a penalty spring) against the threshold mu t (t the normal pressure |LAGS_C|: the current one
// with ALGO_RESO_FROT='NEWTON', that of the last friction loop with 'POINT_FIXE').
//   Stick (|q| < mu t): the tangential pressure is q. Slip: mu t along q / |q|; along the only
// friction direction of a 2D/AXIS point whose statuses are frozen by ALGO_RESO_CONT='POINT_FIXE'
// (senseInStatus), the sliding sense is part of the status (3: backwards), so that a sign change
// of q is a status change and not a force flipping within the Newton iterations.

#include "solver/contact/ContactDefinition.hpp"

#include <Eigen/Dense>
#include <string>

namespace stella::contact {

struct CoulombPoint {
  Eigen::Vector2d base = Eigen::Vector2d::Zero(); // multiplier (STANDARD) or start pressure (PENALISATION)
  double rho = 0.0;                               // COEF_FROT or COEF_PENA_FROT
  double limit = 0.0;                             // mu t, the threshold
  int directions = 1;                             // friction directions (0, 1 or 2)
  bool senseInStatus = false;                     // 2D/AXIS with ALGO_RESO_CONT='POINT_FIXE'
};

// q = base + rho s, zero along the excluded directions.
Eigen::Vector2d coulombIndicator(const CoulombPoint& p, const Eigen::Vector2d& slip);
// 1 sticking, 2 sliding (along q / |q|), 3 sliding backwards (senseInStatus); a point with no
// friction direction slides freely (2); a zero threshold slides whatever the sign of q.
char coulombStatus(const CoulombPoint& p, const Eigen::Vector2d& slip);
// The unit sliding direction of status s >= 2 (zero when q vanishes).
Eigen::Vector2d coulombSlidingDirection(const CoulombPoint& p, char s, const Eigen::Vector2d& slip);
// The tangential pressure of a point in contact with status s (0 for s = 0).
Eigen::Vector2d coulombPressure(const CoulombPoint& p, char s, const Eigen::Vector2d& slip);

// The RESI_FROT criterion: max |t_now - t_before| over max t_now (infinite when every t_now
// vanished and something changed, 0 when nothing did).
double frictionThresholdChange(const Eigen::VectorXd& before, const Eigen::VectorXd& now);

// The friction loop's decision at a converged Newton state on the RESI_FROT criterion (negative:
// no correction yet): Accept; NewtonGoesOn (ALGO_RESO_FROT='NEWTON': the threshold still moved,
// `continuation` says so); NewThreshold (POINT_FIXE: loop `iterations` + 1 with the thresholds of
// now; throws CONTACT_28 past ITER_FROT_MAXI). `what` names the thresholds' places in the message.
enum class FrictionLoop { Accept, NewtonGoesOn, NewThreshold };
FrictionLoop frictionLoopStep(const ContinuousSettings& settings, double criterion, int& iterations,
                              double time, const SourceLocation& at, const std::string& what,
                              std::string& continuation);

} // namespace stella::contact
