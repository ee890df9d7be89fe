#pragma once
// A condition solved inside the Newton loop of STAT_NON_LINE besides the mechanical equations:
// contact (CONTACT keyword). The NewtonDriver calls it at fixed points of each step; without one
// (no CONTACT) nothing of it is built or called, so an analysis without contact costs what it
// cost before.
//
// Call sequence of one step (the same again when a step is cut and restarted):
//   beginStep(u_start, time)                  pairing at the start of the step (REAC_GEOM)
//   repeat (Newton iterations):
//     addForces(u, forces, tangent?)          forces on the structure at u; penalty tangents
//     ... the driver solves K ddu = r with r = F_ext - F_int - C^T lambda + forces ...
//     correct(u, ddu, dlambda, solver)        dual methods: project the correction on the
//                                             admissible set (K^-1 through `solver`)
//   on mechanical convergence: acceptConvergence(u) -> false re-pairs (geometric loop) and the
//   Newton iterations go on; true ends the step.
//   store(step) after acceptance (and once for the initial state, before the first step).
//
// Alarms the constraint raises while solving (interpenetration in a zone only measured,
// geometric loop not converged to 1 %, penalty coefficient at its maximum...) go to the
// diagnostic sink STAT_NON_LINE gives it (the session's: framed in the message file and counted
// in the job diagnostic, <A>_ALARM); without a sink (unit tests) they stay in the step report.

#include "interpreter/Diagnostics.hpp"
#include "solver/nonlinear/SaddleSolver.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <ostream>
#include <string>
#include <vector>

namespace stella {

struct ResultStep;

class StepConstraint {
public:
  virtual ~StepConstraint() = default;

  // The effects it activates, for the log line of STAT_NON_LINE (e.g. "contact DISCRETE
  // CONTRAINTE, geometric loop AUTOMATIQUE").
  virtual std::string effects() const = 0;

  // One line per zone for the effects report of STAT_NON_LINE (groups, algorithm, friction,
  // slave nodes); empty when the constraint has no zones.
  virtual std::vector<std::string> zoneEffects() const { return {}; }

  // What the constraint did over the command, for the time-per-effect line at its end (e.g. "3
  // pairing(s)"); may be empty.
  virtual std::string workSummary() const { return {}; }

  // Start of a step from the converged displacement `u` (physical size).
  virtual void beginStep(const Eigen::VectorXd& u, double time) = 0;

  // Adds the constraint's forces on the structure at the displacement `u` to `forces` (physical
  // size; they enter the residual with a plus sign, like external forces). When `tangent` is not
  // null, appends the tangent contributions -d(forces)/du to be added to the stiffness (penalty
  // methods; dual methods add none).
  virtual void addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                         std::vector<Eigen::Triplet<double>>* tangent) = 0;

  // Whether the tangent contributions are symmetric (chooses the matrix storage).
  virtual bool symmetric() const = 0;
  // The RESI_GLOB_RELA of the iteration just measured at the iterate whose tangent comes next
  // (negative: no relative reference, the absolute test applies). Penalised friction uses it:
  // COEF_MATR_FROT weighs the sliding links' tangent only while it is >= 1e-3, as code_aster does.
  virtual void residualMeasured(double relativeResidual) { (void)relativeResidual; }

  // Dual methods: `ddu`, `dlambda` solve the linearised system with the residual computed with
  // addForces(u); corrects them so that the constraint holds at u + ddu (the solver's last
  // factorisation gives K^-1 with homogeneous relations: solver.solve(f, 0, 0, x, y)). Penalty
  // methods leave them unchanged.
  virtual void correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                       SaddleSolver& solver) = 0;

  // Newton has converged at `u`. Returns true to accept the step; false when the geometric loop
  // paired again and the Newton iterations must go on.
  virtual bool acceptConvergence(const Eigen::VectorXd& u) = 0;

  // Extra text for the convergence-table row of the last iteration (e.g. active links, maximum
  // interpenetration); may be empty.
  virtual std::string iterationNote() const = 0;
  // The header of the columns iterationNote() starts with ("| NAME |" cells, as the table's own), or
  // empty when its note has no columns; asked once per step, after beginStep().
  virtual std::string iterationHeader() const { return {}; }

  // The convergence-table line written when acceptConvergence() refused a converged state.
  virtual std::string continuationNote() const { return "geometric update: contact pairing recomputed"; }

  // Lines written to the message file at the end of an accepted step (geometric iterations,
  // contact iterations, "Nombre de liaisons de contact : N", maximum interpenetration).
  virtual void reportStep(std::ostream& log) const = 0;

  // Stores its fields (CONT_NOEU) in a result step: the state of the last accepted step, or the
  // initial pairing with no forces before the first step.
  virtual void store(ResultStep& step) const = 0;

  // A note added to the singular-stiffness error (a body held only by contact: discrete
  // formulations need springs, notice §4.4.2); empty when it has nothing to say.
  virtual std::string singularNote() const = 0;

  // A note added to the no-convergence error of STAT_NON_LINE (SNL_3) when the constraint knows a
  // likely cause (penalised friction without its tangent); empty when it has nothing to say.
  virtual std::string noConvergenceNote() const { return {}; }

  // Where the constraint's alarms go (null: none, they stay in the step report).
  void setDiagnosticSink(DiagnosticSink* sink) { sink_ = sink; }

protected:
  // Emits an alarm through the sink; false when there is none (the caller then reports it
  // itself).
  bool emitAlarm(const Diagnostic& alarm) const {
    if (sink_ == nullptr) {
      return false;
    }
    sink_->report(alarm);
    return true;
  }

private:
  DiagnosticSink* sink_ = nullptr;
};

} // namespace stella
