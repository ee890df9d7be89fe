// Continuous contact at integration points (see the header).

#include "solver/contact/ContinuousPointContact.hpp"

#include "messages/Messages.hpp"
#include "solver/contact/CellProjection.hpp"
#include "solver/contact/ContactAlarm.hpp"
#include "solver/contact/ContactResultField.hpp"
#include "solver/contact/ContinuousAdaptation.hpp"
#include "solver/contact/ContinuousIntegrationRule.hpp"
#include "solver/contact/MultiplierSchur.hpp"
#include "solver/database/Result.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/nonlinear/SaddleSolver.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <set>

namespace stella::contact {

std::string ContinuousPointContactConstraint::resolutionEffects() const {
  std::vector<std::string> zones;
  for (const auto& z : definition_->zones) {
    if (z.resolve) {
      const auto& c = z.continuous;
      zones.push_back(
          fmt::format("{} INTEGRATION='{}'{}",
                      z.algorithm == ContactAlgorithm::ContinuePenalty
                          ? fmt::format("PENALISATION COEF_PENA_CONT={}", c.penalty)
                          : fmt::format("STANDARD COEF_CONT={}", c.augmentation),
                      integrationName(c.integration),
                      c.integrationOrder > 0 ? fmt::format(" ORDRE_INT={}", c.integrationOrder) : ""));
    }
  }
  return fmt::format("{} (LAGS_C on the slave nodes, {} contact points), ALGO_RESO_CONT={}{}",
                     fmt::join(zones, "; "), points_.size(),
                     definition_->settings.continuous.statusLoop == StatusLoop::Newton ? "NEWTON"
                                                                                       : "POINT_FIXE",
                     penetrationEffects(*definition_, policy_));
}

double ContinuousPointContactConstraint::lambdaAt(const ContactPoint& p) const {
  double l = 0.0;
  for (std::size_t k = 0; k < p.nodes.size(); ++k) {
    if (p.multiplier[k] >= 0) {
      l += p.shape[k] * lambda_[static_cast<std::size_t>(p.multiplier[k])];
    }
  }
  return l;
}

double ContinuousPointContactConstraint::gapAt(const ContactPoint& p, const Eigen::VectorXd& u) const {
  double g = p.gap;
  for (const auto& [e, a] : p.row) {
    g += a * (u(e) - uPairing_(e));
  }
  return g;
}

double ContinuousPointContactConstraint::pressureAt(const ContactPoint& p, double gap) const {
  return p.penalised ? p.rho * gap : lambdaAt(p) + p.rho * gap;
}

double ContinuousPointContactConstraint::indicatorAt(const ContactPoint& p, const Eigen::VectorXd& u) const {
  const double g = gapAt(p, u);
  return p.penalised ? g : lambdaAt(p) + p.rho * g;
}

std::vector<char> ContinuousPointContactConstraint::statusAt(const Eigen::VectorXd& u) const {
  std::vector<char> s(points_.size(), 0);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (q < frozen_.size() && frozen_[q] >= 0) {
      s[q] = static_cast<char>(frozen_[q]);
    } else if (p.paired && p.weight != 0.0) {
      s[q] = indicatorAt(p, u) < 0.0 || closed_[q] != 0 ? 1 : 0; // GLISSIERE: held closed
    }
    if (s[q] != 0 && friction()) {
      s[q] = coulombStatus(coulombAt(q), slipAt(p, u));
    }
  }
  return s;
}

const std::vector<char>& ContinuousPointContactConstraint::currentStatus(const Eigen::VectorXd& u) {
  if (definition_->settings.continuous.statusLoop == StatusLoop::Newton && !useInitial_) {
    status_ = statusAt(u);
  }
  return status_;
}

void ContinuousPointContactConstraint::beginStep(const Eigen::VectorXd& u, double time) {
  lambda_ = lambdaStart_; // a step cut restarts from the multipliers of its start
  lambdaT_ = lambdaTStart_;
  ContactConstraint::beginStep(u, time);
  resetFrictionStep();
  statusIterations_ = 0;
  changes_.assign(points_.size(), 0);
  frozen_.assign(points_.size(), -1);
  continuation_.clear();
  useInitial_ = true;
  lastStatus_.clear();
  status_.assign(points_.size(), 0);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (!firstStep_) {
      status_[q] = p.paired ? contactStart_[q] : 0;
      continue;
    }
    if (!p.paired || p.weight == 0.0) {
      continue;
    }
    const ContinuousZone& c = definition_->zones[static_cast<std::size_t>(p.zone)].continuous;
    const double g = gapAt(p, u);
    status_[q] = c.init == ContactInit::Yes ? 1
                 : c.init == ContactInit::Interpenetrated
                     ? (g < 0.0 && (c.initDistance < 0.0 || -g <= c.initDistance) ? 1 : 0)
                     : 0;
  }
  applyInitialOptions(); // SEUIL_INIT, GLISSIERE
}

void ContinuousPointContactConstraint::addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                                                 std::vector<Eigen::Triplet<double>>* tangent) {
  const std::vector<char>& status = currentStatus(u);
  noteGeometry_ = geometricCriterion(u);
  int active = 0;
  double penetration = 0.0;
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (!p.paired) {
      continue;
    }
    const bool on = status[q] != 0;
    const double g = gapAt(p, u);
    if (on) {
      ++active;
      penetration = std::max(penetration, -g);
      const double pressure = pressureAt(p, g); // -w (lambda + rho g) grad g
      for (const auto& [e, a] : p.row) {
        forces(e) -= p.weight * pressure * a;
      }
    }
    if (tangent != nullptr) {
      const double c = on ? p.rho * p.weight : 0.0; // zeros keep the pattern of the pairing
      for (const auto& [e, a] : p.row) {
        for (const auto& [f, b] : p.row) {
          tangent->emplace_back(e, f, c * a * b);
        }
      }
    }
    if (friction()) {
      addFrictionForces(q, status[q], u, forces, tangent);
    }
  }
  noteActive_ = active;
  notePenetration_ = penetration;
}

void ContinuousPointContactConstraint::normalEquations(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                                                       const std::vector<char>& status,
                                                       MultiplierSystem& sys) const {
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (!p.paired || p.weight == 0.0 || p.penalised) {
      continue; // a penalised point's pressure is eliminated: no equation
    }
    if (status[q] != 0) {
      const double g = gapAt(p, u);
      double adu = 0.0;
      for (const auto& [e, a] : p.row) {
        adu += a * ddu(e);
      }
      for (std::size_t k = 0; k < p.nodes.size(); ++k) {
        const int i = p.multiplier[k];
        if (i < 0 || p.shape[k] == 0.0) {
          continue;
        }
        const double c = p.weight * p.shape[k];
        for (const auto& [e, a] : p.row) {
          sys.row[static_cast<std::size_t>(i)].emplace_back(e, c * a);
        }
        sys.residual(i) += c * (g + adu);
        sys.used[static_cast<std::size_t>(i)] = 1;
      }
    } else {
      const double lp = lambdaAt(p);
      for (std::size_t k = 0; k < p.nodes.size(); ++k) {
        const int i = p.multiplier[k];
        if (i < 0) {
          continue;
        }
        sys.residual(i) -= p.weight * p.shape[k] * lp / p.rho; // -(1/rho) w N_i lambda_p
        for (std::size_t l = 0; l < p.nodes.size(); ++l) {
          if (p.multiplier[l] >= 0) {
            sys.mass(i, p.multiplier[l]) += p.weight * p.shape[k] * p.shape[l] / p.rho;
          }
        }
      }
    }
  }
}

void ContinuousPointContactConstraint::correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu,
                                               Eigen::VectorXd& dlambda, SaddleSolver& solver) {
  const std::vector<char> status = currentStatus(u);
  useInitial_ = false;
  lastStatus_ = status;
  const auto nm = static_cast<Eigen::Index>(multiplierNode_.size());
  if (nm == 0) {
    return;
  }
  recordThreshold();
  const Eigen::Index n = ddu.size();
  MultiplierSystem sys = multiplierSystem(u, ddu, status);
  const auto nu = static_cast<Eigen::Index>(sys.row.size());
  addContactIterations(1);
  // The unknowns: the multipliers of the nodes with a point in contact in their cells (a row of
  // B); the others are 0, as in the nodal formulation (their consistent equation, the block M of
  // the points out of contact, is singular with rules of negative weights or too few points, e.g.
  // GAUSS 3 on TRIA6, when no point is in contact).
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < nu; ++i) {
    if (sys.used[static_cast<std::size_t>(i)] != 0) {
      free.push_back(i);
      continue;
    }
    double& value = multiplierValue(i);
    sys.residual += sys.mass.col(i) * value; // the residuals with this multiplier set to 0
    value = 0.0;
  }
  const auto nf = static_cast<Eigen::Index>(free.size());
  const auto unknown = [&](Eigen::Index j) {
    return static_cast<std::size_t>(free[static_cast<std::size_t>(j)]);
  };
  Eigen::MatrixXd s(nf, nf);
  Eigen::VectorXd r(nf);
  std::vector<Eigen::Index> coupled; // positions in `free` with a force column
  for (Eigen::Index i = 0; i < nf; ++i) {
    r(i) = sys.residual(free[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < nf; ++j) {
      s(i, j) = sys.mass(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
    }
    if (!sys.row[unknown(i)].empty() || !sys.column[unknown(i)].empty()) {
      coupled.push_back(i);
    }
  }
  // S += B K^-1 C^T by blocks of columns (C = B + column)
  const auto addColumn = [&](Eigen::Index j, double factor, auto&& v) {
    for (const auto& [e, a] : sys.row[unknown(j)]) {
      v(e) += factor * a;
    }
    for (const auto& [e, a] : sys.column[unknown(j)]) {
      v(e) += factor * a;
    }
  };
  constexpr std::size_t block = 64;
  for (std::size_t first = 0; first < coupled.size(); first += block) {
    const std::size_t cols = std::min(block, coupled.size() - first);
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(cols));
    for (std::size_t j = 0; j < cols; ++j) {
      addColumn(coupled[first + j], 1.0, x.col(static_cast<Eigen::Index>(j)));
    }
    solver.solveHomogeneous(x);
    for (Eigen::Index i : coupled) {
      for (const auto& [e, a] : sys.row[unknown(i)]) {
        for (std::size_t j = 0; j < cols; ++j) {
          s(i, coupled[first + j]) += a * x(e, static_cast<Eigen::Index>(j));
        }
      }
    }
  }
  Eigen::VectorXd dl;
  if (nf == 0) {
    dl = Eigen::VectorXd();
  } else {
    // non-symmetric with ALGO_RESO_FROT='NEWTON' and sliding points
    dl = solveMultiplierSchur(s, r, sys.symmetric, [&](Eigen::Index i) {
      redundant(multiplierOfUnknown(static_cast<Eigen::Index>(unknown(i))));
    });
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  bool any = false;
  for (Eigen::Index j = 0; j < nf; ++j) {
    const std::size_t i = unknown(j);
    multiplierValue(static_cast<Eigen::Index>(i)) += dl(j);
    any = any || !sys.row[i].empty() || !sys.column[i].empty();
    addColumn(j, dl(j), f);
  }
  if (!any) {
    return;
  }
  applyMultiplierForces(f, ddu, dlambda, solver);
}

void ContinuousPointContactConstraint::redundant(int multiplier) const {
  throw UserError(msg::make(
      "CONTACT_11.2",
      {{"time", time_},
       {"node_name", definition_->mesh->nodeName(multiplierNode_[static_cast<std::size_t>(multiplier)])}},
      definition_->location));
}

bool ContinuousPointContactConstraint::acceptResolution(const Eigen::VectorXd& u) {
  continuation_.clear();
  const auto& c = definition_->settings.continuous;
  const std::vector<char> now = statusAt(u);
  const bool newton = c.statusLoop == StatusLoop::Newton;
  const std::vector<char>& used = newton ? lastStatus_ : status_;
  penalisedPressures(u);
  if (points_.empty() || now == used || (newton && lastStatus_.empty() && now == status_)) {
    if ((!friction() || acceptFriction(u)) && acceptPenetration(u)) {
      acceptFrictionStep(u); // the tangential pressures of the state accepted
      return true;
    }
    return false;
  }
  int changed = 0;
  int frozen = 0;
  for (std::size_t q = 0; q < now.size(); ++q) {
    if (q >= used.size() || now[q] == used[q]) {
      continue;
    }
    ++changed;
    // ADAPTATION='CYCLAGE': a point that went in and out of contact twice in the step keeps the
    // status its multiplier asks for (in contact while compressed) for the rest of it.
    const std::string& adaptation =
        definition_->zones[static_cast<std::size_t>(points_[q].zone)].continuous.adaptation;
    if (++changes_[q] >= 4 && (adaptation == "CYCLAGE" || adaptation == "TOUT")) {
      const ContactPoint& p = points_[q];
      frozen_[q] = (p.penalised ? gapAt(p, u) : lambdaAt(p)) < 0.0 ? 1 : 0;
      ++frozen;
    }
  }
  if (frozen > 0) {
    noteAlarm(alarmLine(msg::make("CONTACT_27.2", {{"frozen", frozen}, {"time", time_}})));
  }
  status_ = statusAt(u);
  ++statusIterations_;
  const auto count = static_cast<int>(points_.size());
  const int cap = newton                ? 2 * count + 10
                  : c.iterationsPerNode ? c.statusIterationFactor * static_cast<int>(multiplierNode_.size())
                                        : c.maxStatusIterations;
  if (statusIterations_ > cap) {
    throw UserError(msg::make("CONTACT_26.2", {{"time", time_}, {"cap", cap}, {"changed", changed}},
                              definition_->location)
                        .withNote(newton ? msg::text("CONTACT_26.n1") : msg::text("CONTACT_26.n2")));
  }
  lastStatus_ = status_;
  continuation_ =
      fmt::format("contact status changed on {} contact point(s): Newton iterations go on", changed);
  return false;
}

bool ContinuousPointContactConstraint::acceptPenetration(const Eigen::VectorXd& u) {
  std::vector<double> penetration(definition_->zones.size(), 0.0);
  bool any = false;
  for (const ContactPoint& p : points_) {
    if (p.paired && p.penalised && p.weight != 0.0) {
      auto& d = penetration[static_cast<std::size_t>(p.zone)];
      d = std::max(d, -gapAt(p, u));
      any = true;
    }
  }
  if (!any) {
    return true;
  }
  const std::vector<std::string> raised =
      raisePenalties(*definition_, policy_, penetration, time_, penaltyFactor_,
                     [this](std::string text) { noteAlarm(std::move(text)); });
  if (raised.empty()) {
    return true;
  }
  for (ContactPoint& p : points_) {
    if (p.penalised) {
      p.rho = definition_->zones[static_cast<std::size_t>(p.zone)].continuous.penalty *
              penaltyFactor_[static_cast<std::size_t>(p.zone)];
    }
  }
  continuation_ = fmt::format("penalty raised ({}): Newton iterations go on", fmt::join(raised, "; "));
  return false;
}

void ContinuousPointContactConstraint::penalisedPressures(const Eigen::VectorXd& u) {
  if (std::find(penalisedNode_.begin(), penalisedNode_.end(), 1) == penalisedNode_.end()) {
    return;
  }
  const std::vector<char> status = statusAt(u);
  std::vector<double> pressure(multiplierNode_.size(), 0.0);
  std::vector<double> weight(multiplierNode_.size(), 0.0);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (!p.paired || !p.penalised) {
      continue;
    }
    const double value = status[q] != 0 ? pressureAt(p, gapAt(p, u)) : 0.0;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      if (p.multiplier[k] >= 0) {
        pressure[static_cast<std::size_t>(p.multiplier[k])] += p.weight * p.shape[k] * value;
        weight[static_cast<std::size_t>(p.multiplier[k])] += p.weight * p.shape[k];
      }
    }
  }
  for (std::size_t i = 0; i < multiplierNode_.size(); ++i) {
    if (penalisedNode_[i] != 0) {
      lambda_[i] = weight[i] > 0.0 ? pressure[i] / weight[i] : 0.0;
    }
  }
}

void ContinuousPointContactConstraint::nodalForces(const Eigen::VectorXd& u, std::vector<double>& force,
                                                   std::vector<char>& touching) const {
  force.assign(multiplierNode_.size(), 0.0);
  touching.assign(multiplierNode_.size(), 0);
  const std::vector<char> status = statusAt(u);
  for (std::size_t q = 0; q < points_.size(); ++q) {
    const ContactPoint& p = points_[q];
    if (status[q] == 0) {
      continue;
    }
    const double pressure = pressureAt(p, gapAt(p, u));
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      const int i = p.multiplier[k];
      if (i >= 0 && p.shape[k] != 0.0) {
        force[static_cast<std::size_t>(i)] -= p.weight * p.shape[k] * pressure;
        touching[static_cast<std::size_t>(i)] = 1;
      }
    }
  }
}

std::vector<LinkState> ContinuousPointContactConstraint::resolvedStates(const Eigen::VectorXd& u) const {
  const Eigen::VectorXd g = gapsAt(u);
  std::vector<double> force;
  std::vector<char> touching;
  nodalForces(u, force, touching);
  std::vector<LinkState> states(rows_.link.size());
  for (std::size_t r = 0; r < states.size(); ++r) {
    const NodeId node = links_[static_cast<std::size_t>(rows_.link[r])].slave;
    const int i = multiplierOfNode_[static_cast<std::size_t>(node)];
    states[r].gap = g(static_cast<Eigen::Index>(r));
    if (i >= 0 && touching[static_cast<std::size_t>(i)] != 0) {
      states[r].normalForce = force[static_cast<std::size_t>(i)];
      states[r].status = LinkStatus::Sliding;
    }
  }
  frictionStates(u, states);
  return states;
}

void ContinuousPointContactConstraint::accepted(const std::vector<LinkState>& rowStates) {
  (void)rowStates;
  lambdaStart_ = lambda_;
  lambdaTStart_ = lambdaT_;
  pressureTStart_ = pressureT_;
  contactStart_ = status_;
  holdClosed();
  firstStep_ = false;
}

std::string ContinuousPointContactConstraint::continuationNote() const {
  return continuation_.empty() ? ContactConstraint::continuationNote() : continuation_;
}

void ContinuousPointContactConstraint::store(ResultStep& step) const {
  ContactConstraint::store(step);
  const auto [out, c0] =
      multiplierDepl(step, friction() ? static_cast<std::size_t>(tangentComponents()) : 0U);
  if (out == nullptr) {
    return;
  }
  for (std::size_t i = 0; i < multiplierNode_.size(); ++i) {
    const auto n = static_cast<std::size_t>(multiplierNode_[i]);
    out->value(n, c0) = lambda_[i];
    out->setDefined(n, c0);
  }
  if (friction()) {
    storeFriction(*out, c0 + 1);
  }
  step.fields["DEPL"] = out;
}

std::string ContinuousPointContactConstraint::singularNote() const {
  return "with FORMULATION='CONTINUE' a body held only by contact is held once its contact points are in "
         "contact (the augmented term COEF_CONT x w x grad g grad g of the points in contact stiffens it): "
         "CONTACT_INIT='OUI' puts every contact point in contact at the first iteration; otherwise impose "
         "DDL_IMPO on one of its points or hold it with springs of small stiffness (notice §4.4.2)";
}

} // namespace stella::contact
