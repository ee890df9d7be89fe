// Coulomb friction of the continuous contact at integration points (ContinuousPointContact.hpp): the
// law of ContinuousCoulombLaw at each point along its friction directions, the forces and their
// tangent, and the equations of the tangential multipliers LAGS_F on the slave nodes.

#include "solver/contact/ContinuousPointContact.hpp"

#include <algorithm>
#include <cmath>

namespace stella::contact {

namespace {

double rowDot(const std::vector<std::pair<int, double>>& row, const Eigen::VectorXd& v) {
  double s = 0.0;
  for (const auto& [e, a] : row) {
    s += a * v(e);
  }
  return s;
}

} // namespace

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

double& ContinuousPointContactConstraint::multiplierValue(Eigen::Index i) {
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  if (i < nm) {
    return lambda_[static_cast<std::size_t>(i)];
  }
  const Eigen::Index c = tangentComponents();
  return lambdaT_[static_cast<std::size_t>((i - nm) / c)]((i - nm) % c);
}

int ContinuousPointContactConstraint::multiplierOfUnknown(Eigen::Index i) const {
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  return static_cast<int>(i < nm ? i : (i - nm) / tangentComponents());
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
  Eigen::Vector2d s = Eigen::Vector2d::Zero();
  for (int j = 0; j < p.directions; ++j) {
    for (const auto& [e, a] : p.frictionRow[static_cast<std::size_t>(j)]) {
      s(j) += a * (u(e) - uStart_(e));
    }
  }
  return s;
}

Eigen::Vector2d ContinuousPointContactConstraint::lambdaTAt(const ContactPoint& p) const {
  Eigen::Vector2d l = Eigen::Vector2d::Zero();
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
  // on the point's friction directions: B times the multiplier (or the start pressure) on (t1, t2)
  c.base = p.basis * (z.frictionPenalised ? pressureTStart_[q] : lambdaTAt(p));
  c.rho = z.frictionPenalised ? z.frictionPenalty : z.frictionAugmentation;
  c.limit = coulombOf(p) * thresholdAt(q);
  c.directions = p.directions;
  c.senseInStatus = p.directions == 1 && definition_->settings.continuous.statusLoop != StatusLoop::Newton;
  return c;
}

Eigen::Vector2d ContinuousPointContactConstraint::tangentialPressureAt(std::size_t q, char s,
                                                                       const Eigen::VectorXd& u) const {
  return s == 0 ? Eigen::Vector2d::Zero() : coulombPressure(coulombAt(q), s, slipAt(points_[q], u));
}

void ContinuousPointContactConstraint::addFrictionForces(std::size_t q, char s, const Eigen::VectorXd& u,
                                                         Eigen::VectorXd& forces,
                                                         std::vector<Eigen::Triplet<double>>* tangent) const {
  const ContactPoint& p = points_[q];
  const Eigen::Vector2d pt = tangentialPressureAt(q, s, u);
  for (int j = 0; j < p.directions; ++j) {
    for (const auto& [e, a] : p.frictionRow[static_cast<std::size_t>(j)]) {
      forces(e) -= p.weight * pt(j) * a;
    }
  }
  if (tangent == nullptr) {
    return;
  }
  // sticking: rho_t w F^T F; sliding along two directions: w rho_t alpha F^T P F, the turn of the
  // direction (along one: none; its dependence on LAGS_C goes in the multipliers' system); zeros
  // keep the pattern
  const CoulombPoint c = coulombAt(q);
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
  if (s == 1) {
    k = c.rho * p.weight * Eigen::Matrix2d::Identity();
  } else if (s == 2 && p.directions == 2) {
    const Eigen::Vector2d ind = coulombIndicator(c, slipAt(p, u));
    const double size = ind.norm();
    if (size > 0.0 && c.limit > 0.0) {
      const Eigen::Vector2d e = ind / size;
      k = (p.weight * c.rho * c.limit / size) * (Eigen::Matrix2d::Identity() - e * e.transpose());
    }
  }
  for (int a = 0; a < p.directions; ++a) {
    for (int b = 0; b < p.directions; ++b) {
      for (const auto& [e, x] : p.frictionRow[static_cast<std::size_t>(a)]) {
        for (const auto& [f, y] : p.frictionRow[static_cast<std::size_t>(b)]) {
          tangent->emplace_back(e, f, k(a, b) * x * y);
        }
      }
    }
  }
}

// The equations of point q along its friction directions j (and the excluded ones, j >= directions,
// of the tangent components): stick s_j = 0 (a row); slide (1/rho_t)(mu t e_j - (B lambda_t)_j) = 0,
// linearised in u (two directions: the row alpha (P F)_j) and in lambda_t (I - alpha P); out of
// contact and excluded (1/rho_t)(0 - (B lambda_t)_j) = 0.
ContinuousPointContactConstraint::PointFrictionEquations
ContinuousPointContactConstraint::pointFrictionEquations(std::size_t q, char s, const Eigen::VectorXd& u,
                                                         const Eigen::VectorXd& ddu) const {
  const ContactPoint& p = points_[q];
  const int nd = tangentComponents();
  PointFrictionEquations eq;
  const Eigen::Vector2d bl = p.basis * lambdaTAt(p);
  const int first = s == 0 ? 0 : p.directions; // the directions without friction
  for (int j = first; j < nd; ++j) {
    eq.mass(j, j) = 1.0;
    eq.massResidual(j) = -bl(j);
  }
  if (s == 0 || p.directions == 0) {
    return eq;
  }
  const CoulombPoint c = coulombAt(q);
  const Eigen::Vector2d slip = slipAt(p, u);
  if (s == 1) {
    for (int j = 0; j < p.directions; ++j) {
      const auto& f = p.frictionRow[static_cast<std::size_t>(j)];
      for (const auto& [e, a] : f) {
        eq.row[static_cast<std::size_t>(j)].emplace_back(e, p.weight * a);
      }
      eq.residual(j) = p.weight * (slip(j) + rowDot(f, ddu));
    }
    return eq;
  }
  const Eigen::Vector2d e = coulombSlidingDirection(c, s, slip);
  for (int j = 0; j < p.directions; ++j) {
    eq.mass(j, j) = 1.0;
    eq.massResidual(j) = c.limit * e(j) - bl(j);
  }
  const double size = coulombIndicator(c, slip).norm();
  if (p.directions == 2 && size > 0.0 && c.limit > 0.0) {
    const double alpha = c.limit / size;
    const Eigen::Matrix2d pa = alpha * (Eigen::Matrix2d::Identity() - e * e.transpose());
    eq.mass.topLeftCorner(2, 2) -= pa;
    for (int j = 0; j < 2; ++j) {
      for (int l = 0; l < 2; ++l) {
        const auto& f = p.frictionRow[static_cast<std::size_t>(l)];
        for (const auto& [dof, a] : f) {
          eq.row[static_cast<std::size_t>(j)].emplace_back(dof, p.weight * pa(j, l) * a);
        }
        eq.residual(j) += p.weight * pa(j, l) * rowDot(f, ddu);
      }
    }
  }
  return eq;
}

void ContinuousPointContactConstraint::addPointFrictionEquations(const ContactPoint& p,
                                                                 const PointFrictionEquations& eq, double rho,
                                                                 bool inContact,
                                                                 MultiplierSystem& sys) const {
  // on the components c of the nodes' LAGS_F: B^T of the directions' equations
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  const int nd = tangentComponents();
  const Eigen::Matrix2d mass = p.basis.transpose() * eq.mass * p.basis / rho;
  const Eigen::Vector2d massResidual = p.basis.transpose() * eq.massResidual / rho;
  for (std::size_t k = 0; k < p.nodes.size(); ++k) {
    const int i = p.multiplier[k];
    if (i < 0) {
      continue;
    }
    const double wn = p.weight * p.shape[k];
    for (int c = 0; c < nd; ++c) {
      const Eigen::Index ti = nm + nd * i + c;
      sys.residual(ti) += wn * massResidual(c);
      for (std::size_t l = 0; l < p.nodes.size(); ++l) {
        const int m = p.multiplier[l];
        for (int d = 0; d < nd && m >= 0; ++d) {
          sys.mass(ti, nm + nd * m + d) += wn * p.shape[l] * mass(c, d);
        }
      }
      if (!inContact || p.shape[k] == 0.0) {
        continue;
      }
      sys.used[static_cast<std::size_t>(ti)] = 1;
      for (int j = 0; j < nd; ++j) {
        const double b = p.basis(j, c) * p.shape[k];
        if (b == 0.0) {
          continue;
        }
        for (const auto& [dof, a] : eq.row[static_cast<std::size_t>(j)]) {
          sys.row[static_cast<std::size_t>(ti)].emplace_back(dof, b * a);
        }
        sys.residual(ti) += b * eq.residual(j);
      }
    }
  }
}

void ContinuousPointContactConstraint::addSlidingCoupling(std::size_t q, const Eigen::Vector2d& e,
                                                          MultiplierSystem& sys) const {
  // the sliding force -w mu t_p e . F_p with t_p = -lambda_p: the column of lambda_i gets
  // -w mu N_i e . F_p; the sliding equations (1/rho_t) w N_k B_jc mu t_p e_j their derivative
  const ContactPoint& p = points_[q];
  const double mu = coulombOf(p);
  const CoulombPoint c = coulombAt(q);
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  const int nd = tangentComponents();
  const bool unknowns = !definition_->zones[static_cast<std::size_t>(p.zone)].continuous.frictionPenalised;
  const Eigen::Vector2d be = p.basis.transpose() * e; // on the components of LAGS_F
  sys.symmetric = false;
  for (std::size_t l = 0; l < p.nodes.size(); ++l) {
    const int m = p.multiplier[l];
    if (m < 0 || p.shape[l] == 0.0) {
      continue;
    }
    for (int j = 0; j < p.directions; ++j) {
      for (const auto& [dof, a] : p.frictionRow[static_cast<std::size_t>(j)]) {
        sys.column[static_cast<std::size_t>(m)].emplace_back(dof, -p.weight * mu * e(j) * p.shape[l] * a);
      }
    }
    for (std::size_t k = 0; k < p.nodes.size() && unknowns; ++k) {
      const int i = p.multiplier[k];
      for (int cc = 0; cc < nd && i >= 0; ++cc) {
        sys.mass(nm + nd * i + cc, m) += p.weight * p.shape[k] * p.shape[l] * mu * be(cc) / c.rho;
      }
    }
  }
}

void ContinuousPointContactConstraint::frictionEquations(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                                                         const std::vector<char>& status,
                                                         MultiplierSystem& sys) const {
  if (!friction()) {
    return;
  }
  const bool newton = newtonFriction();
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (!p.paired || p.weight == 0.0 || p.penalised) {
      continue;
    }
    const CoulombPoint c = coulombAt(q);
    const bool unknowns = frictionUnknowns() &&
                          !definition_->zones[static_cast<std::size_t>(p.zone)].continuous.frictionPenalised;
    const bool sliding = status[q] >= 2 && p.directions > 0;
    if (sliding && newton && lambdaAt(p) < 0.0) {
      const Eigen::Vector2d e = coulombSlidingDirection(c, status[q], slipAt(p, u));
      if (e.squaredNorm() > 0.0) {
        addSlidingCoupling(q, e, sys);
      }
    }
    if (unknowns) {
      addPointFrictionEquations(p, pointFrictionEquations(q, status[q], u, ddu), c.rho, status[q] != 0, sys);
    }
  }
}

} // namespace stella::contact
