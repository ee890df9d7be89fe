// NewtonDriver: prediction, residuals, corrections and the convergence table of one step.

#include "solver/nonlinear/NewtonDriver.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

NewtonDriver::NewtonDriver(MechanicalSystem& system, NewtonSettings settings, std::ostream& log)
    : system_(system), settings_(settings), log_(log) {}

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
  std::vector<Eigen::Triplet<double>> triplets;
  system_.assembler().run(start.displacement, du, start.points, option, {&triplets, nullptr, nullptr});
  factorizeMatrix(triplets, start.displacement + du, !checked_);
  checked_ = true;
}

bool NewtonDriver::symmetric() const {
  return system_.behaviours().allSymmetric() && (constraint_ == nullptr || constraint_->symmetric());
}

void NewtonDriver::factorizeMatrix(std::vector<Eigen::Triplet<double>>& triplets, const Eigen::VectorXd& u,
                                   bool check) {
  if (constraint_ != nullptr) {
    Eigen::VectorXd unused = Eigen::VectorXd::Zero(u.size());
    constraint_->addForces(u, unused, &triplets);
  }
  try {
    system_.solver().factorize(system_.matrix(triplets), check, symmetric());
  } catch (const UserError& e) {
    const std::string note = constraint_ != nullptr ? constraint_->singularNote() : std::string();
    if (note.empty() || e.first().id != "SOLVE_1") {
      throw;
    }
    Diagnostic d = e.first();
    throw UserError(std::move(d).withNote(note));
  }
}

Eigen::VectorXd NewtonDriver::constraintForces(const Eigen::VectorXd& u) {
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(u.size());
  if (constraint_ != nullptr) {
    constraint_->addForces(u, forces, nullptr);
  }
  return forces;
}

StepOutcome NewtonDriver::step(const MechanicalState& start, double time, MechanicalState& end) {
  const int n = system_.dofs().physicalCount();
  const Eigen::VectorXd fext = system_.externalForces(time);
  const Eigen::VectorXd g = system_.relationValues(time);
  const Eigen::VectorXd imposed = system_.eliminatedValues(time);
  const auto& eliminated = system_.solver().eliminated();
  Eigen::VectorXd du = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd lambda = start.multipliers;
  StepOutcome out;
  if (constraint_ != nullptr) {
    constraint_->beginStep(start.displacement, time);
  }
  log_ << fmt::format("   INST {:<12g}\n", time);
  log_ << "   ------------------------------------------------------------------------------\n";
  log_ << "   | ITER | RESI_GLOB_RELA | RESI_GLOB_MAXI | WHERE (MAXI)            | MATRIX    |\n";
  log_ << "   ------------------------------------------------------------------------------\n";
  // Prediction.
  std::string matrixNote;
  if (!settings_.tangentMatrix || settings_.elasticPrediction) {
    if (!elasticFactorized_ || settings_.tangentMatrix) {
      factorize(start, du, behaviour::Option::ElasticTangent, true);
      elasticFactorized_ = !settings_.tangentMatrix;
      matrixNote = "ELASTIQUE";
    }
  } else {
    factorize(start, du, behaviour::Option::PredictionTangent, true);
    matrixNote = "TANGENTE";
  }
  {
    // Residual at the start of the step with the new loads.
    Eigen::VectorXd fint = Eigen::VectorXd::Zero(n);
    end.points = start.points;
    system_.assembler().run(start.displacement, du, start.points, behaviour::Option::ResidualOnly,
                            {nullptr, &fint, nullptr});
    Eigen::VectorXd r =
        fext - fint - system_.solver().transposeTimes(lambda) + constraintForces(start.displacement);
    for (int i = 0; i < n; ++i) {
      if (eliminated[static_cast<std::size_t>(i)]) {
        r(i) = 0.0;
      }
    }
    Eigen::VectorXd c = g - system_.solver().times(start.displacement);
    Eigen::VectorXd p = imposed - start.displacement;
    Eigen::VectorXd ddu;
    Eigen::VectorXd dl;
    system_.solver().solve(r, c, p, ddu, dl);
    if (constraint_ != nullptr) {
      constraint_->correct(start.displacement, ddu, dl, system_.solver());
    }
    du += ddu;
    lambda += dl;
  }
  // The geometric loop of a constraint extends the iteration budget by ITER_GLOB_MAXI per
  // re-pairing; the constraint bounds the number of re-pairings (ITER_GEOM_MAXI).
  int lastIteration = settings_.iterGlobMaxi;
  for (int iter = 0; iter <= lastIteration; ++iter) {
    const bool updateMatrix = settings_.tangentMatrix && settings_.reacIter > 0 && iter < lastIteration &&
                              ((iter + 1) % settings_.reacIter == 0);
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::VectorXd fint = Eigen::VectorXd::Zero(n);
    end.points = start.points;
    const behaviour::Option option = updateMatrix ? behaviour::Option::Full : behaviour::Option::ResidualOnly;
    const auto status = system_.assembler().run(start.displacement, du, start.points, option,
                                                {updateMatrix ? &triplets : nullptr, &fint, &end.points});
    if (!status.ok()) {
      log_ << fmt::format("   | {:4d} | behaviour integration failed in cell {}\n", iter,
                          system_.model().mesh->cellName(*status.failedCell));
      out.integrationFailed = true;
      return out;
    }
    const Eigen::VectorXd reactions = system_.solver().transposeTimes(lambda);
    const Eigen::VectorXd forces = constraintForces(start.displacement + du);
    Eigen::VectorXd r = fext - fint - reactions + forces;
    Eigen::VectorXd reference = fext - reactions + forces;
    for (int i = 0; i < n; ++i) {
      if (eliminated[static_cast<std::size_t>(i)]) {
        reference(i) = fint(i);
        r(i) = 0.0;
      }
    }
    Eigen::Index where = 0;
    const double maxi = n > 0 ? r.cwiseAbs().maxCoeff(&where) : 0.0;
    const double denominator = n > 0 ? reference.cwiseAbs().maxCoeff() : 0.0;
    // When the forces and reactions vanish (a structure unloaded to zero stress) the relative
    // residual has no scale: the largest reference of the converged steps gives it.
    const double scale = std::max(denominator, 1.0e-6 * forceScale_);
    const double rela = scale > 0.0 ? maxi / scale : maxi;
    const std::string at =
        n > 0 ? system_.dofs().describe(static_cast<int>(where), *system_.model().mesh) : "-";
    const bool ok = (settings_.resiGlobRela <= 0.0 || rela <= settings_.resiGlobRela) &&
                    (settings_.resiGlobMaxi <= 0.0 || maxi <= settings_.resiGlobMaxi);
    log_ << fmt::format("   | {:4d} | {:14.6e} | {:14.6e} | {:<23} | {:<9} |{}\n", iter, rela, maxi,
                        at.substr(0, 23), matrixNote,
                        constraint_ != nullptr ? " " + constraint_->iterationNote() : std::string());
    out.iterations = iter;
    out.resiRela = rela;
    out.resiMaxi = maxi;
    const bool accepted =
        ok && (constraint_ == nullptr || constraint_->acceptConvergence(start.displacement + du));
    if (ok && !accepted) {
      // The geometric loop paired again: at least one more correction with the new pairing.
      log_ << "   |      | geometric update: contact pairing recomputed\n";
      lastIteration = iter + 1 + settings_.iterGlobMaxi;
    }
    if (accepted) {
      out.converged = true;
      forceScale_ = std::max(forceScale_, denominator);
      end.time = time;
      end.displacement = start.displacement + du;
      end.multipliers = lambda;
      log_ << "   ------------------------------------------------------------------------------\n";
      return out;
    }
    if (iter == lastIteration) {
      break;
    }
    matrixNote = "";
    if (updateMatrix) {
      factorizeMatrix(triplets, start.displacement + du, false);
      matrixNote = "TANGENTE";
    }
    const Eigen::VectorXd c = g - system_.solver().times(start.displacement + du);
    Eigen::VectorXd ddu;
    Eigen::VectorXd dl;
    system_.solver().solve(r, c, Eigen::VectorXd::Zero(n), ddu, dl);
    if (constraint_ != nullptr) {
      constraint_->correct(start.displacement + du, ddu, dl, system_.solver());
    }
    du += ddu;
    lambda += dl;
  }
  log_ << "   ------------------------------------------------------------------------------\n";
  return out;
}

} // namespace stella
