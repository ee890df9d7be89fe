// NewtonDriver: prediction, residuals, corrections, line search and the convergence table of one
// step.

#include "solver/nonlinear/NewtonDriver.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/nonlinear/PhaseTimes.hpp"
#include "solver/nonlinear/SymmetricTangent.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace stella {

namespace {

// RESI_GLOB_RELA of an iteration: max |residual| / the reference (residualReference). When that
// reference vanishes (below the round-off of the last reference and of this step's forces, or of
// 1) the relative criterion has no scale: as code_aster does (U4.51.04 §6, alarm
// MECANONLINE2_98), RESI_GLOB_RELA is shown as -1 and the residual is tested in absolute, against
// RESI_GLOB_MAXI when given, else RESI_GLOB_RELA x the largest of the reference of the last step
// converged under load and of this step's forces (a contact that pushes bodies apart until no
// force is left); the relative test returns to force as soon as the load does.
// A reference below the round-off of the internal forces it is made of has vanished too, and a
// residual at that round-off is converged: `forceRoundOff` = 1e-12 x max |K_ii| x max |u| (the
// forces of a body moved rigidly by u cancel to eps x |K| |u| times the terms summed; 1e-12 keeps
// a margin over them, as the 1e-12 x the last reference above). Without it the first steps of a
// stiff body driven rigidly before any contact (a LAC patch only comes into contact when its mean
// gap closes: ssnv506_h25_lac) compare a round-off residual with 1e-6 of a round-off reference
// and never converge.
struct RelativeTest {
  double rela = 0.0;
  bool ok = false;
  bool nullLoad = false;
  double tolerance = 0.0; // absolute, when nullLoad
};

RelativeTest relativeTest(double maxi, double denominator, double lastReference, double forceRoundOff,
                          const NewtonSettings& s) {
  if (s.resiGlobRela <= 0.0) {
    return {denominator > 0.0 ? maxi / denominator : -1.0, true, false, 0.0};
  }
  const double roundOff =
      std::max({1.0e-12 * lastReference, forceRoundOff, std::numeric_limits<double>::epsilon()});
  if (denominator > roundOff) {
    return {maxi / denominator, maxi <= s.resiGlobRela * denominator, false, 0.0};
  }
  const double tolerance =
      s.resiGlobMaxi > 0.0 ? s.resiGlobMaxi : std::max(s.resiGlobRela * lastReference, forceRoundOff);
  return {-1.0, maxi <= tolerance, true, tolerance};
}

double largestDiagonal(const StiffnessMatrix& k) {
  double largest = 0.0;
  for (int i = 0; i < k.size(); ++i) {
    largest = std::max(largest, std::fabs(k.diagonal(i)));
  }
  return largest;
}

} // namespace

NewtonDriver::NewtonDriver(MechanicalSystem& system, NewtonSettings settings, std::ostream& log)
    : system_(system), settings_(std::move(settings)), log_(log) {}

MechanicalState NewtonDriver::initialState(double time) const {
  MechanicalState s;
  s.time = time;
  s.displacement = Eigen::VectorXd::Zero(system_.dofs().physicalCount());
  s.multipliers = Eigen::VectorXd::Zero(system_.relationCount());
  s.points = zeroPointState(system_.model(), system_.behaviours().maxInternalVariables());
  return s;
}

void NewtonDriver::factorize(const MechanicalState& start, const Eigen::VectorXd& du,
                             behaviour::Option option, bool first) {
  (void)first;
  StiffnessMatrix& k = system_.stiffness(symmetric());
  {
    PhaseClock clock(system_.phases().assembly);
    system_.assembler().run(start.displacement, du, start.points, option, {nullptr, nullptr, nullptr, &k});
  }
  factorizeMatrix(k, start.displacement + du);
}

double NewtonDriver::solverSeconds() const {
  const SaddleSolver::Timings& t = system_.solver().timings();
  return t.bordering + t.analysis + t.factorisation + t.solve;
}

template <class Call> decltype(auto) NewtonDriver::timedConstraint(Call&& call) {
  struct Clock {
    NewtonDriver& driver;
    double solverStart;
    std::chrono::steady_clock::time_point start;
    ~Clock() {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      driver.system_.phases().contact += std::max(0.0, elapsed - (driver.solverSeconds() - solverStart));
    }
  } clock{*this, solverSeconds(), std::chrono::steady_clock::now()};
  return call();
}

bool NewtonDriver::symmetric() const {
  return system_.behaviours().allSymmetric() && (constraint_ == nullptr || constraint_->symmetric());
}

namespace {

// The largest diagonal term of the constraint's tangent (penalties E_N, E_T) over the largest of
// the structure's stiffness K: a pivot is null relative to K, not to the penalties.
double penaltyRatio(const StiffnessMatrix& k, const std::vector<Eigen::Triplet<double>>& triplets) {
  double penalty = 0.0;
  for (const auto& t : triplets) {
    if (t.row() == t.col()) {
      penalty = std::max(penalty, std::fabs(t.value()));
    }
  }
  const double stiffness = largestDiagonal(k);
  return stiffness > 0.0 ? std::max(1.0, penalty / stiffness) : 1.0;
}

} // namespace

void NewtonDriver::factorizeMatrix(StiffnessMatrix& k, const Eigen::VectorXd& u) {
  stiffnessScale_ = largestDiagonal(k); // the structure's alone: before the constraint's terms
  StiffnessMatrix* matrix = &k;
  if (constraint_ != nullptr) {
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd unused = Eigen::VectorXd::Zero(u.size());
    timedConstraint([&] { constraint_->addForces(u, unused, &triplets); });
    system_.solver().setPenaltyRatio(penaltyRatio(k, triplets)); // k: the structure's alone here
    if (!symmetric() && k.storage() == linalg::Storage::Upper) {
      // the constraint's tangent turned unsymmetric (friction): K in full storage
      matrix = &system_.stiffness(false);
      matrix->add(k);
    }
    matrix->add(triplets);
  }
  if (settings_.symmetrizeTangent && matrix->storage() == linalg::Storage::Full) {
    matrix = &symmetricPart(*matrix, system_.stiffness(true));
  }
  try {
    const bool symmetricMatrix = symmetric() || settings_.symmetrizeTangent;
    ++(symmetricMatrix ? symmetricFactorisations_ : unsymmetricFactorisations_);
    system_.solver().factorize(*matrix, symmetricMatrix);
  } catch (const UserError& e) {
    const std::string note = constraint_ != nullptr ? constraint_->singularNote() : std::string();
    if (note.empty() || e.first().id != "SOLVE_1") {
      throw;
    }
    Diagnostic d = e.first();
    throw UserError(std::move(d).withNote(note));
  }
  factorized_ = true;
}

Eigen::VectorXd NewtonDriver::constraintForces(const Eigen::VectorXd& u) {
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(u.size());
  if (constraint_ != nullptr) {
    timedConstraint([&] { constraint_->addForces(u, forces, nullptr); });
  }
  return forces;
}

AssemblyStatus NewtonDriver::residual(const MechanicalState& start, const Eigen::VectorXd& du,
                                      const Eigen::VectorXd& lambda, const Eigen::VectorXd& fext,
                                      behaviour::Option option, AssemblyOutput out, Eigen::VectorXd& r) {
  const int n = system_.dofs().physicalCount();
  Eigen::VectorXd local = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd& fint = out.internalForces != nullptr ? *out.internalForces : local;
  fint.setZero(n);
  out.internalForces = &fint;
  AssemblyStatus status;
  {
    PhaseClock clock(system_.phases().assembly);
    status = system_.assembler().run(start.displacement, du, start.points, option, out);
  }
  r = fext - fint - system_.solver().transposeTimes(lambda) + constraintForces(start.displacement + du);
  const auto& eliminated = system_.solver().eliminated();
  for (int i = 0; i < n; ++i) {
    if (eliminated[static_cast<std::size_t>(i)]) {
      r(i) = 0.0;
    }
  }
  return status;
}

bool NewtonDriver::predictionMatrixDue() const {
  return !factorized_ || convergedSteps_ == 0 ||
         (settings_.reacIncr > 0 && convergedSteps_ % settings_.reacIncr == 0);
}

std::string NewtonDriver::predict(const MechanicalState& start, double time, const Eigen::VectorXd& fext,
                                  const Eigen::VectorXd& g, const Eigen::VectorXd& imposed,
                                  Eigen::VectorXd& du, Eigen::VectorXd& lambda) {
  const int n = system_.dofs().physicalCount();
  const bool extrapolate =
      settings_.prediction == Prediction::Extrapolated && lastIncrement_.size() == n && lastStepLength_ > 0.0;
  const bool given = extrapolate || settings_.prediction == Prediction::Computed;
  std::string matrixNote;
  // The matrix of the prediction (and of the first corrections when REAC_ITER does not update
  // it; a given increment needs none when the first correction reassembles the tangent).
  if (!settings_.tangentMatrix) {
    if (!elasticFactorized_) {
      factorize(start, du, behaviour::Option::ElasticTangent, true);
      elasticFactorized_ = true;
      matrixNote = "ELASTIQUE";
    }
  } else if (predictionMatrixDue() && !(given && settings_.reacIter == 1)) {
    const bool elastic = settings_.prediction == Prediction::Elastic;
    factorize(start, du, elastic ? behaviour::Option::ElasticTangent : behaviour::Option::PredictionTangent,
              true);
    matrixNote = elastic ? "ELASTIQUE" : "TANGENTE";
  }
  if (given) {
    // An increment given rather than solved for: the relations are restored by the first
    // correction; the eliminated DOFs take their values now.
    // The multipliers are part of the extrapolated increment (code_aster's LAGR DOFs of DEPL);
    // a computed displacement has none: the first correction finds the reactions.
    const double ratio = (time - start.time) / lastStepLength_;
    du = extrapolate ? Eigen::VectorXd(lastIncrement_ * ratio)
                     : Eigen::VectorXd(settings_.computedDisplacement(time) - start.displacement);
    if (extrapolate && lastMultiplierIncrement_.size() == lambda.size()) {
      lambda += ratio * lastMultiplierIncrement_;
    }
    const auto& eliminated = system_.solver().eliminated();
    for (int i = 0; i < n; ++i) {
      if (eliminated[static_cast<std::size_t>(i)]) {
        du(i) = imposed(i) - start.displacement(i);
      }
    }
    return matrixNote;
  }
  // Residual at the start of the step with the new loads, solved with the prediction matrix.
  Eigen::VectorXd r;
  residual(start, du, lambda, fext, behaviour::Option::ResidualOnly, {}, r);
  const Eigen::VectorXd c = g - system_.solver().times(start.displacement);
  const Eigen::VectorXd p = imposed - start.displacement;
  Eigen::VectorXd ddu;
  Eigen::VectorXd dl;
  system_.solver().solve(r, c, p, ddu, dl);
  if (constraint_ != nullptr) {
    timedConstraint([&] { constraint_->correct(start.displacement, ddu, dl, system_.solver()); });
  }
  du += ddu;
  lambda += dl;
  return matrixNote;
}

double NewtonDriver::lineSearch(const MechanicalState& start, const Eigen::VectorXd& du,
                                const Eigen::VectorXd& ddu, const Eigen::VectorXd& lambda,
                                const Eigen::VectorXd& fext, const Eigen::VectorXd& r0, int& iterations) {
  const LineSearchSettings& ls = settings_.lineSearch;
  // f(rho) = r(u + du + rho ddu) . ddu vanishes where the energy is stationary along ddu;
  // f(0) > 0 for a descent direction.
  const double f0 = r0.dot(ddu);
  if (!(f0 > 0.0) || ls.maxIterations <= 0) {
    return 1.0;
  }
  double rhoPrevious = 0.0;
  double fPrevious = f0;
  double rho = 1.0;
  double best = 1.0;
  double bestF = std::numeric_limits<double>::infinity();
  Eigen::VectorXd r;
  for (int k = 0; k < ls.maxIterations; ++k) {
    const Eigen::VectorXd trial = du + rho * ddu;
    ++iterations;
    if (!residual(start, trial, lambda, fext, behaviour::Option::ResidualOnly, {}, r).ok()) {
      break; // the behaviour cannot integrate this far: keep the best length so far
    }
    const double f = r.dot(ddu);
    if (std::fabs(f) < bestF) {
      bestF = std::fabs(f);
      best = rho;
    }
    if (std::fabs(f) <= ls.relativeResidual * f0 || f == fPrevious) {
      break;
    }
    double next = rho - f * (rho - rhoPrevious) / (f - fPrevious);
    next = std::clamp(next, ls.rhoMin, ls.rhoMax);
    if (std::fabs(next) < ls.rhoExcluded) {
      next = std::copysign(ls.rhoExcluded, next);
    }
    rhoPrevious = rho;
    fPrevious = f;
    rho = next;
  }
  return best;
}

double NewtonDriver::residualReference(const Eigen::VectorXd& fext, const Eigen::VectorXd& reactions,
                                       const Eigen::VectorXd& fint, const Eigen::VectorXd& forces) const {
  const auto& eliminated = system_.solver().eliminated();
  double reference = 0.0;
  for (Eigen::Index i = 0; i < fext.size(); ++i) {
    const double applied =
        eliminated[static_cast<std::size_t>(i)] ? std::fabs(fint(i)) : std::fabs(fext(i) - reactions(i));
    reference = std::max({reference, applied, std::fabs(forces(i))});
  }
  return reference;
}

StepOutcome NewtonDriver::step(const MechanicalState& start, double time, MechanicalState& end) {
  const int n = system_.dofs().physicalCount();
  const Eigen::VectorXd fext = system_.externalForces(time);
  const Eigen::VectorXd g = system_.relationValues(time);
  const Eigen::VectorXd imposed = system_.eliminatedValues(time);
  const auto& eliminated = system_.solver().eliminated();
  if (forceScale_ <= 0.0 && n > 0 && start.multipliers.size() == system_.dofs().lagrangeCount()) {
    // No step converged under load yet: the forces and reactions of the initial state (ETAT_INIT)
    // give the reference of a step whose load vanishes.
    Eigen::VectorXd initial =
        system_.externalForces(start.time) - system_.solver().transposeTimes(start.multipliers);
    for (int i = 0; i < n; ++i) {
      if (eliminated[static_cast<std::size_t>(i)]) {
        initial(i) = 0.0;
      }
    }
    forceScale_ = initial.cwiseAbs().maxCoeff();
  }
  Eigen::VectorXd du = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd lambda = start.multipliers;
  StepOutcome out;
  if (constraint_ != nullptr) {
    timedConstraint([&] { constraint_->beginStep(start.displacement, time); });
  }
  {
    // The forces the step starts with: the new loads, the reactions of the start and the
    // constraint's forces at the start (a penalised interpenetration of the pairing).
    Eigen::VectorXd fint = Eigen::VectorXd::Zero(n);
    stepScale_ = residualReference(fext, system_.solver().transposeTimes(start.multipliers), fint,
                                   constraintForces(start.displacement));
  }
  // With RECH_LINEAIRE a column gives the length rho of the line search that led to the row.
  const bool rhoColumn = settings_.lineSearch.enabled;
  const std::string extraHeader =
      (columns_ != nullptr ? columns_->header(start.displacement, start.points) : "") +
      (constraint_ != nullptr ? constraint_->iterationHeader() : std::string());
  const std::string rule = std::string(78, '-') + (rhoColumn ? std::string(11, '-') : std::string()) +
                           std::string(extraHeader.size(), '-');
  log_ << fmt::format("   INST {:<12g}\n", time);
  log_ << "   " << rule << "\n";
  log_ << "   | ITER | RESI_GLOB_RELA | RESI_GLOB_MAXI | WHERE (MAXI)            | MATRIX    |"
       << (rhoColumn ? " RHO      |" : "") << extraHeader << "\n";
  log_ << "   " << rule << "\n";
  double rho = 1.0;
  std::string matrixNote;
  try {
    matrixNote = predict(start, time, fext, g, imposed, du, lambda);
  } catch (const UserError& e) {
    // A singular prediction tangent after converged steps: the matrix is the tangent of the last
    // converged state, which a shorter step cannot change, so the run stops at once; but the
    // state the material reached is the likely cause, not a free motion of the model: say it
    // first.
    if (e.first().id != "SOLVE_1" || convergedSteps_ == 0 || settings_.prediction == Prediction::Elastic ||
        !settings_.tangentMatrix) {
      throw;
    }
    Diagnostic d = e.first();
    d.notes.insert(
        d.notes.begin(),
        fmt::format("the matrix is the tangent of the last converged state (INST {:g}), after {} converged "
                    "step(s): perfectly plastic points (D_SIGM_EPSI = 0) have no stiffness along their flow, "
                    "and a region that flows freely (a limit load, or an incompressible flow the "
                    "mean-dilatation '_SI' cells allow) makes it singular; NEWTON=_F(MATRICE='ELASTIQUE') "
                    "with a larger CONVERGENCE ITER_GLOB_ELAS iterates with the elastic matrix, which "
                    "stays regular (a shorter step would not change this matrix)",
                    start.time, convergedSteps_));
    throw UserError(std::move(d));
  }
  // The geometric loop of a constraint extends the iteration budget by ITER_GLOB_MAXI per
  // re-pairing; the constraint bounds the number of re-pairings (ITER_GEOM_MAXI).
  int lastIteration = settings_.iterGlobMaxi;
  bool nullLoadNoted = false;
  for (int iter = 0; iter <= lastIteration; ++iter) {
    const bool updateMatrix = settings_.tangentMatrix && settings_.reacIter > 0 && iter < lastIteration &&
                              ((iter + 1) % settings_.reacIter == 0);
    StiffnessMatrix* k = updateMatrix ? &system_.stiffness(symmetric()) : nullptr;
    Eigen::VectorXd fint;
    end.points = start.points;
    const behaviour::Option option = updateMatrix ? behaviour::Option::Full : behaviour::Option::ResidualOnly;
    Eigen::VectorXd r;
    const auto status = residual(start, du, lambda, fext, option, {nullptr, &fint, &end.points, k}, r);
    if (!status.ok()) {
      log_ << fmt::format("   | {:4d} | behaviour integration failed in cell {}\n", iter,
                          system_.model().mesh->cellName(*status.failedCell));
      out.integrationFailed = true;
      return out;
    }
    const Eigen::VectorXd reactions = system_.solver().transposeTimes(lambda);
    const Eigen::VectorXd forces = constraintForces(start.displacement + du);
    Eigen::Index where = 0;
    const double maxi = n > 0 ? r.cwiseAbs().maxCoeff(&where) : 0.0;
    const double denominator = residualReference(fext, reactions, fint, forces);
    stepScale_ = std::max(stepScale_, denominator);
    const double forceRoundOff =
        n > 0 ? 1.0e-12 * stiffnessScale_ * (start.displacement + du).cwiseAbs().maxCoeff() : 0.0;
    const RelativeTest test =
        relativeTest(maxi, denominator, std::max(forceScale_, stepScale_), forceRoundOff, settings_);
    const double rela = test.rela;
    if (constraint_ != nullptr) {
      constraint_->residualMeasured(rela);
    }
    if (test.nullLoad && !nullLoadNoted) {
      nullLoadNoted = true;
      if (std::max(forceScale_, stepScale_) <= 0.0 && settings_.resiGlobMaxi <= 0.0 && maxi > forceRoundOff) {
        throw UserError(msg::make("SNL_11", {{"time", time}, {"maxi", maxi}}));
      }
      log_ << fmt::format(
          "   |      | zero load and reactions: RESI_GLOB_RELA shown as -1, test in absolute, "
          "RESI_GLOB_MAXI <= {:.3e}{}\n",
          test.tolerance,
          settings_.resiGlobMaxi > 0.0 ? std::string(" (given)")
          : test.tolerance > settings_.resiGlobRela * std::max(forceScale_, stepScale_)
              ? std::string(" = the round-off of the internal forces, 1e-12 x max K_ii x max |u|")
              : fmt::format(" = RESI_GLOB_RELA x {:.3e}, the largest reference of the last step converged "
                            "under load and of this step's forces",
                            std::max(forceScale_, stepScale_)));
    }
    const std::string at =
        n > 0 ? system_.dofs().describe(static_cast<int>(where), *system_.model().mesh) : "-";
    const bool ok =
        std::isfinite(maxi) && criteriaHold({{settings_.resiGlobRela > 0.0, test.ok},
                                             {settings_.resiGlobMaxi > 0.0, maxi <= settings_.resiGlobMaxi}},
                                            settings_.verif);
    log_ << fmt::format("   | {:4d} | {:14.6e} | {:14.6e} | {:<23} | {:<9} |{}{}{}\n", iter, rela, maxi, at,
                        matrixNote, rhoColumn ? fmt::format(" {:<8.4g} |", rho) : std::string(),
                        columns_ != nullptr ? columns_->row(start.displacement + du, end.points)
                                            : std::string(),
                        constraint_ != nullptr ? " " + constraint_->iterationNote() : std::string());
    out.iterations = iter;
    out.resiRela = rela;
    out.resiMaxi = maxi;
    const bool accepted = ok && (constraint_ == nullptr || timedConstraint([&] {
                                   return constraint_->acceptConvergence(start.displacement + du);
                                 }));
    if (ok && !accepted) {
      // The geometric loop paired again: at least one more correction with the new pairing.
      log_ << "   |      | " << constraint_->continuationNote() << "\n";
      lastIteration = iter + 1 + settings_.iterGlobMaxi;
    }
    if (accepted) {
      out.converged = true;
      if (!test.nullLoad) {
        forceScale_ = denominator;
      }
      end.time = time;
      end.displacement = start.displacement + du;
      end.multipliers = lambda;
      lastIncrement_ = du;
      lastMultiplierIncrement_ = lambda - start.multipliers;
      lastStepLength_ = time - start.time;
      ++convergedSteps_;
      log_ << "   " << rule << "\n";
      return out;
    }
    if (iter == lastIteration) {
      break;
    }
    matrixNote = "";
    if (updateMatrix) {
      try {
        factorizeMatrix(*k, start.displacement + du);
      } catch (const UserError& e) {
        if (e.first().id != "SOLVE_1") {
          throw;
        }
        log_ << fmt::format("   | {:4d} | the tangent matrix is singular: the step fails\n", iter);
        log_ << "   " << rule << "\n";
        out.singularTangent = e.first();
        factorized_ = false; // the backend holds no usable factorisation now
        elasticFactorized_ = false;
        return out;
      }
      matrixNote = "TANGENTE";
    }
    const Eigen::VectorXd c = g - system_.solver().times(start.displacement + du);
    Eigen::VectorXd ddu;
    Eigen::VectorXd dl;
    system_.solver().solve(r, c, Eigen::VectorXd::Zero(n), ddu, dl);
    if (constraint_ != nullptr) {
      timedConstraint([&] { constraint_->correct(start.displacement + du, ddu, dl, system_.solver()); });
    }
    rho = settings_.lineSearch.enabled
              ? lineSearch(start, du, ddu, lambda + dl, fext, r, out.lineSearchIterations)
              : 1.0;
    du += rho * ddu;
    lambda += rho * dl;
  }
  log_ << "   " << rule << "\n";
  return out;
}

} // namespace stella
