// Penalised discrete contact and friction coupled with the Newton iterations of STAT_NON_LINE.

#include "solver/contact/PenaltyContactConstraint.hpp"

#include "messages/Messages.hpp"
#include "solver/contact/ContactAlarm.hpp"
#include "solver/contact/SaddleStiffness.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace stella::contact {

PenaltyContactConstraint::PenaltyContactConstraint(std::shared_ptr<const ContactDefinition> definition,
                                                   const DofMap& dofs,
                                                   std::optional<FailurePolicy> interpenetration)
    : ContactConstraint(std::move(definition), dofs), friction_(definition_->hasFriction()),
      policy_(interpenetration) {}

std::string PenaltyContactConstraint::resolutionEffects() const {
  std::vector<std::string> en;
  for (const auto& z : definition_->zones) {
    if (z.resolve) {
      en.push_back(friction_ ? fmt::format("E_N={} E_T={} COULOMB={} COEF_MATR_FROT={}", z.normalPenalty,
                                           z.tangentPenalty, z.coulomb, z.frictionMatrixCoefficient)
                             : fmt::format("E_N={}", z.normalPenalty));
    }
  }
  std::string s = fmt::format("PENALISATION ({})", fmt::join(en, "; "));
  if (policy_) {
    s += policy_->action == FailurePolicy::Action::AdaptPenalty
             ? fmt::format(", E_N adapted above PENE_MAXI={} (COEF_MAXI={})", policy_->maxPenetration,
                           policy_->maxCoefficient)
             : fmt::format(", stop above PENE_MAXI={}", policy_->maxPenetration);
  }
  return s;
}

void PenaltyContactConstraint::beginStep(const Eigen::VectorXd& u, double time) {
  ContactConstraint::beginStep(u, time); // pairs (or not) and calls paired()
  closedThisStep_.assign(static_cast<std::size_t>(rows_.problem.A.rows()), 0);
  lastTangentStatuses_.clear();
  if (residualBelowThreshold_ || statusesSettled_) {
    residualBelowThreshold_ = false; // the prediction of a step: COEF_MATR_FROT as given
    statusesSettled_ = false;
    applyMatrixCoefficients();
  }
}

void PenaltyContactConstraint::residualMeasured(double relativeResidual) {
  // code_aster's threshold on the global residual (its discrete friction matrix): below 1e-3 the
  // factor of the sliding links' tangent is 1 whatever COEF_MATR_FROT.
  const bool below = relativeResidual >= 0.0 && relativeResidual < 1e-3;
  if (below != residualBelowThreshold_ && friction_) {
    residualBelowThreshold_ = below;
    applyMatrixCoefficients();
  }
}

void PenaltyContactConstraint::applyMatrixCoefficients() {
  const auto m = static_cast<Eigen::Index>(rows_.link.size());
  parameters_.matrixCoefficient.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const ContactLink& l = links_[static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)])];
    const ContactZone& z = definition_->zones[static_cast<std::size_t>(l.zone)];
    parameters_.matrixCoefficient(i) =
        residualBelowThreshold_ || statusesSettled_ ? 1.0 : z.frictionMatrixCoefficient;
  }
}

void PenaltyContactConstraint::updateParameters() {
  const auto m = static_cast<Eigen::Index>(rows_.link.size());
  parameters_.friction = friction_;
  parameters_.normalPenalty.resize(m);
  parameters_.tangentPenalty.resize(m);
  parameters_.coulomb.resize(m);
  parameters_.slipOffset.resize(0, 2);
  for (Eigen::Index i = 0; i < m; ++i) {
    const ContactLink& l = links_[static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)])];
    const ContactZone& z = definition_->zones[static_cast<std::size_t>(l.zone)];
    double en = z.normalPenalty * factor_;
    if (policy_ && policy_->action == FailurePolicy::Action::AdaptPenalty) {
      en = std::min(en, std::max(z.normalPenalty, policy_->maxCoefficient));
    }
    parameters_.normalPenalty(i) = en;
    parameters_.tangentPenalty(i) = z.tangentPenalty;
    parameters_.coulomb(i) = z.coulomb;
  }
  applyMatrixCoefficients();
  if (!friction_) {
    return;
  }
  // Slip since the step start not seen by u - u_pairing, plus the elastic slip carried over.
  const Eigen::VectorXd before = uPairing_ - uStart_;
  const Eigen::VectorXd s1 = rows_.friction.T1 * before;
  const Eigen::VectorXd s2 =
      rows_.friction.T2.rows() > 0 ? Eigen::VectorXd(rows_.friction.T2 * before) : Eigen::VectorXd::Zero(m);
  parameters_.slipOffset.resize(m, 2);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    const ContactLink& l = links_[k];
    parameters_.slipOffset(i, 0) = s1(i) + dot(elasticSlip_[k], l.tangent1);
    parameters_.slipOffset(i, 1) = s2(i) + dot(elasticSlip_[k], l.tangent2);
  }
}

void PenaltyContactConstraint::paired() {
  elasticSlip_.resize(links_.size(), Point3{0, 0, 0});
  updateParameters();
}

namespace {

// Zero entries for the blocks a link couples (its A row, and its T rows with friction).
void addZeroOuter(std::vector<Eigen::Triplet<double>>& t, const SparseRows& ra, Eigen::Index a,
                  const SparseRows& rb, Eigen::Index b) {
  for (SparseRows::InnerIterator i(ra, a); i; ++i) {
    for (SparseRows::InnerIterator j(rb, b); j; ++j) {
      t.emplace_back(static_cast<int>(i.col()), static_cast<int>(j.col()), 0.0);
    }
  }
}

} // namespace

void PenaltyContactConstraint::addPatternOfOpenLinks(const PenaltyEvaluation& e,
                                                     std::vector<Eigen::Triplet<double>>& tangent) const {
  // The matrix keeps the same sparsity pattern while the pairing does not change, whichever
  // links are open: the linear solver's analysis is reused instead of redone at every change of
  // contact status.
  for (std::size_t i = 0; i < e.status.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    if (e.status[i] != LinkStatus::Open) {
      continue;
    }
    addZeroOuter(tangent, rows_.problem.A, row, rows_.problem.A, row);
    if (friction_) {
      addZeroOuter(tangent, rows_.friction.T1, row, rows_.friction.T1, row);
      addZeroOuter(tangent, rows_.friction.T1, row, rows_.problem.A, row);
      if (rows_.friction.T2.rows() > 0) {
        addZeroOuter(tangent, rows_.friction.T2, row, rows_.friction.T2, row);
        addZeroOuter(tangent, rows_.friction.T1, row, rows_.friction.T2, row);
        addZeroOuter(tangent, rows_.friction.T2, row, rows_.friction.T1, row);
        addZeroOuter(tangent, rows_.friction.T2, row, rows_.problem.A, row);
      }
    }
  }
}

PenaltyEvaluation PenaltyContactConstraint::evaluate(const Eigen::VectorXd& u) const {
  return evaluatePenalty(rows_.problem, friction_ ? &rows_.friction : nullptr, parameters_, u - uPairing_);
}

void PenaltyContactConstraint::addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                                         std::vector<Eigen::Triplet<double>>* tangent) {
  if (rows_.link.empty()) {
    return;
  }
  PenaltyEvaluation e = evaluate(u);
  if (tangent != nullptr && friction_) {
    // The statuses (open, sticking, sliding) of this iterate are those of the last tangent's: the
    // fixed point on the friction forces has nothing left to settle, the whole tangent converges
    // quadratically from here (stella's rule beside code_aster's threshold on the residual).
    const bool settled = e.status == lastTangentStatuses_;
    lastTangentStatuses_ = e.status;
    if (settled != statusesSettled_) {
      statusesSettled_ = settled;
      applyMatrixCoefficients();
      e = evaluate(u);
    }
  }
  forces += e.force;
  if (tangent != nullptr) {
    tangent->insert(tangent->end(), e.tangent.begin(), e.tangent.end());
    addPatternOfOpenLinks(e, *tangent);
    symmetric_ = e.symmetric;
  }
  noteActive_ = e.activeLinks;
  notePenetration_ = e.maxInterpenetration;
}

namespace {

// The rows `keep` of `a`.
SparseRows selectRows(const SparseRows& a, const std::vector<Eigen::Index>& keep) {
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t r = 0; r < keep.size(); ++r) {
    for (SparseRows::InnerIterator it(a, keep[r]); it; ++it) {
      t.emplace_back(static_cast<int>(r), static_cast<int>(it.col()), it.value());
    }
  }
  SparseRows s(static_cast<Eigen::Index>(keep.size()), a.cols());
  s.setFromTriplets(t.begin(), t.end());
  return s;
}

} // namespace

void PenaltyContactConstraint::correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu,
                                       Eigen::VectorXd& dlambda, SaddleSolver& solver) {
  // The matrix of the solve holds E_N A_i^T A_i for the links active at u (gap < 0): they move
  // with the penalised law. A link open at u is free in that matrix, so the solve may push it
  // through the master by what the structure alone would move it (E_N times that is the force
  // the next residual would see: with E_N 1e7 times the structure's stiffness, Newton then
  // cycles between two active sets). Its status is resolved here instead, on the condensed
  // rows of the open links, with the compliance 1/E_N on the diagonal of their Schur
  // complement: the penalised law lambda = E_N max(0, -gap) written as a regularised dual
  // problem, solved by the active-set method of CONTRAINTE (which it becomes as E_N grows).
  const Eigen::Index m = rows_.problem.A.rows();
  if (m == 0) {
    return;
  }
  const Eigen::VectorXd gap = gapsAt(u);
  const Eigen::VectorXd moved = gap + rows_.problem.A * ddu;
  if (closedThisStep_.size() != static_cast<std::size_t>(m)) {
    closedThisStep_.assign(static_cast<std::size_t>(m), 0); // paired again: a new set of rows
  }
  std::vector<Eigen::Index> open;
  bool entering = false;
  for (Eigen::Index i = 0; i < m; ++i) {
    char& closed = closedThisStep_[static_cast<std::size_t>(i)];
    if (gap(i) < 0.0) {
      closed = 1;
    } else if (closed != 0 && !rows_.problem.isBilateral(i)) {
      open.push_back(i);
      entering = entering || moved(i) < 0.0;
    }
  }
  if (!entering) {
    return;
  }
  const auto n = static_cast<Eigen::Index>(open.size());
  ContactProblem problem{selectRows(rows_.problem.A, open), Eigen::VectorXd(n), {}};
  DualOptions options;
  options.rightHandSidesPerSolve = definition_->settings.rightHandSidesPerSolve;
  options.iterationFactor = definition_->settings.contactIterationFactor;
  options.stopIfSingular = false; // the compliance keeps S + C regular
  options.computeDisplacement = false;
  options.symmetric = symmetric_; // the tangent of the last factorisation
  options.compliance.resize(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    problem.gap(r) = moved(open[static_cast<std::size_t>(r)]);
    options.compliance(r) = 1.0 / parameters_.normalPenalty(open[static_cast<std::size_t>(r)]);
  }
  SaddleStiffness k(solver, dlambda.size(), ddu.size());
  DualResult result;
  try {
    result = solveActiveSet(problem, k, Eigen::VectorXd::Zero(ddu.size()), options);
  } catch (const ContactNotConverged& e) {
    throw UserError(msg::make("CONTACT_17", {{"time", time_}, {"iterations", e.result.iterations}, {"n", n}},
                              definition_->location));
  }
  addContactIterations(result.iterations);
  if (result.lambda.size() == 0 || result.lambda.cwiseAbs().maxCoeff() == 0.0) {
    return;
  }
  // ddu + K^-1 A_open^T lambda: the links that close carry E_N times their penetration.
  Eigen::VectorXd x;
  Eigen::VectorXd y;
  k.solveWithMultipliers(problem.A.transpose() * result.lambda, x, y);
  ddu += x;
  if (y.size() == dlambda.size()) {
    dlambda += y;
  }
}

std::string PenaltyContactConstraint::singularCause() const {
  return "with PENALISATION the matrix holds E_N only for the links that penetrate at the iterate "
         "(gap < 0): at the first iteration of a step a body that only touches its master, or is apart "
         "from it, gets no stiffness from contact, so the stiffness must be invertible without the "
         "contact conditions, as for every discrete algorithm";
}

std::string PenaltyContactConstraint::noConvergenceNote() const {
  bool withoutTangent = false;
  for (const auto& z : definition_->zones) {
    withoutTangent = withoutTangent || (friction_ && z.resolve && z.frictionMatrixCoefficient == 0.0);
  }
  if (!withoutTangent) {
    return {};
  }
  return "with penalised friction and COEF_MATR_FROT = 0 the matrix has no term for the sliding links "
         "while RESI_GLOB_RELA >= 1e-3: their friction force COULOMB x E_N x penetration follows the "
         "normal forces as a fixed point, which converges linearly when the friction changes the normal "
         "forces much (COULOMB near 1, a stiff contact), and may not reach 1e-3, below which the whole "
         "tangent is used; COEF_MATR_FROT = 1 adds it from the first iteration (notice §3.3.2: it "
         "accelerates convergence), or raise ITER_GLOB_MAXI";
}

std::vector<LinkState> PenaltyContactConstraint::resolvedStates(const Eigen::VectorXd& u) const {
  const PenaltyEvaluation e = evaluate(u);
  const Eigen::VectorXd gaps = gapsAt(u);
  std::vector<LinkState> states(rows_.link.size());
  Eigen::VectorXd s1;
  Eigen::VectorXd s2;
  if (friction_) {
    const Eigen::VectorXd step = u - uStart_;
    s1 = rows_.friction.T1 * step;
    s2 = rows_.friction.T2.rows() > 0 ? Eigen::VectorXd(rows_.friction.T2 * step)
                                      : Eigen::VectorXd::Zero(static_cast<Eigen::Index>(states.size()));
  }
  for (std::size_t i = 0; i < states.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    LinkState& s = states[i];
    s.gap = gaps(row);
    s.normalForce = e.normalForce(row);
    s.status = e.status[i];
    if (friction_ && s.status != LinkStatus::Open) {
      s.slip = {s1(row), s2(row)};
      s.friction = {e.frictionForce(row, 0), e.frictionForce(row, 1)};
    }
  }
  return states;
}

bool PenaltyContactConstraint::acceptResolution(const Eigen::VectorXd& u) {
  if (!policy_ || rows_.link.empty()) {
    return true;
  }
  const double pene = evaluate(u).maxInterpenetration;
  if (pene <= policy_->maxPenetration) {
    return true;
  }
  if (policy_->action == FailurePolicy::Action::Stop) {
    throw UserError(msg::make("CONTACT_14.2",
                              {{"pene", pene}, {"max_penetration", policy_->maxPenetration}, {"time", time_}},
                              definition_->location));
  }
  const double before = parameters_.normalPenalty.size() > 0 ? parameters_.normalPenalty.maxCoeff() : 0.0;
  factor_ *= 10.0;
  updateParameters();
  const double after = parameters_.normalPenalty.size() > 0 ? parameters_.normalPenalty.maxCoeff() : 0.0;
  if (after <= before) {
    factor_ /= 10.0;
    noteAlarm(alarmLine(msg::make("CONTACT_15", {{"pene", pene},
                                                 {"max_penetration", policy_->maxPenetration},
                                                 {"max_coefficient", policy_->maxCoefficient}})));
    return true;
  }
  noteAlarm(alarmLine(msg::make(
      "CONTACT_16", {{"pene", pene}, {"max_penetration", policy_->maxPenetration}, {"after", after}})));
  return false;
}

void PenaltyContactConstraint::accepted(const std::vector<LinkState>& rowStates) {
  if (!friction_) {
    return;
  }
  for (std::size_t i = 0; i < rowStates.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    const ContactLink& l = links_[k];
    const double et = parameters_.tangentPenalty(static_cast<Eigen::Index>(i));
    if (rowStates[i].status == LinkStatus::Open || et <= 0.0) {
      elasticSlip_[k] = Point3{0, 0, 0};
      continue;
    }
    // t = -E_T s_elastic: the elastic slip that gives the converged friction force.
    elasticSlip_[k] =
        (-1.0 / et) * (rowStates[i].friction[0] * l.tangent1 + rowStates[i].friction[1] * l.tangent2);
  }
}

} // namespace stella::contact
