#pragma once
// The time stepping of STAT_NON_LINE over the instants of INCREMENT, with the step cutting of
// DEFI_LIST_INST ECHEC (EVENEMENT='ERREUR'): when a step fails (Newton does not converge or a
// behaviour fails to integrate) and ACTION='DECOUPE' (SUBD_METHODE='MANUEL'), the step is cut
// into SUBD_PAS equal sub-steps whose instants are inserted in the list, as code_aster does;
// a sub-step that fails is cut again, down to SUBD_NIVEAU levels of subdivision (the instants of
// the list are level 0, the sub-steps of a level-L step level L+1: a step of level
// SUBD_NIVEAU is not cut again) and never into sub-steps shorter than SUBD_PAS_MINI.
// ACTION='ARRET' stops at the first failure. The message file shows each cut.

#include "solver/nonlinear/NewtonDriver.hpp"

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace stella {

// ECHEC / EVENEMENT='ERREUR' of DEFI_LIST_INST.
struct CutPolicy {
  bool subdivide = true; // ACTION='DECOUPE' (false: 'ARRET')
  int subdivisions = 4;  // SUBD_PAS
  int maxLevel = 3;      // SUBD_NIVEAU
  double minStep = 0.0;  // SUBD_PAS_MINI
};

// A converged step as the stepper reports it.
struct ConvergedStep {
  int index = 0;          // number of the computed instant (1, 2, ...; sub-steps included)
  double time = 0.0;      // the instant reached
  double startTime = 0.0; // the instant the step started from
  int level = 0;          // 0 for an instant of the list, L for a sub-step of level L
  bool last = false;      // the last instant of the list
  int cuts = 0;           // steps cut so far
  StepOutcome outcome;
};

// Why the stepping stopped before the end.
struct SteppingFailure {
  double startTime = 0.0;
  double time = 0.0; // the instant that could not be reached
  int level = 0;
  StepOutcome outcome;
  std::string reason; // why no further cut: ARRET, SUBD_NIVEAU or SUBD_PAS_MINI reached
};

struct SteppingResult {
  bool completed = false;
  int computedSteps = 0; // converged steps, sub-steps included
  int cuts = 0;          // steps cut
  SteppingFailure failure;
};

class TimeStepper {
public:
  // Computes one step from a converged state to `time`; on convergence `end` holds the state.
  using StepFunction =
      std::function<StepOutcome(const MechanicalState& start, double time, MechanicalState& end)>;
  // Called after each converged step with the new state (already the stepper's current state).
  using ConvergedFunction = std::function<void(const MechanicalState& state, const ConvergedStep& step)>;
  // Called before each attempt of a step (the progress line erases itself there).
  using AttemptFunction = std::function<void(double startTime, double time)>;

  TimeStepper(CutPolicy policy, std::ostream& log) : policy_(policy), log_(log) {}

  void onAttempt(AttemptFunction f) { attempt_ = std::move(f); }

  // Steps from `state` (at instants.front()) through every later instant of `instants`
  // (increasing). `state` ends as the last converged state.
  SteppingResult run(MechanicalState& state, const std::vector<double>& instants, const StepFunction& step,
                     const ConvergedFunction& converged);

private:
  // Why a step of `level` and length `length` cannot be cut (empty when it can).
  std::string refusal(int level, double length) const;

  CutPolicy policy_;
  std::ostream& log_;
  AttemptFunction attempt_;
};

} // namespace stella
