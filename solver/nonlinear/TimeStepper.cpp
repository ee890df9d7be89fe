// TimeStepper: the instants still to compute, cut on failure.

#include "solver/nonlinear/TimeStepper.hpp"

#include <deque>
#include <fmt/format.h>

namespace stella {

namespace {

struct PendingInstant {
  double time = 0.0;
  int level = 0;
};

std::string failureCause(const StepOutcome& o) {
  if (o.integrationFailed) {
    return "the behaviour integration failed";
  }
  if (o.singularTangent) {
    return fmt::format("the tangent matrix became singular at iteration {}", o.iterations);
  }
  return fmt::format("Newton did not converge in {} iterations, RESI_GLOB_RELA = {:.3e}", o.iterations,
                     o.resiRela);
}

} // namespace

std::string TimeStepper::refusal(int level, double length) const {
  if (!policy_.subdivide) {
    return "DEFI_LIST_INST ECHEC ACTION='ARRET'";
  }
  if (level >= policy_.maxLevel) {
    return fmt::format("SUBD_NIVEAU={} levels of subdivision reached", policy_.maxLevel);
  }
  const double sub = length / policy_.subdivisions;
  if (sub < policy_.minStep) {
    return fmt::format("a sub-step of {:g} would be shorter than SUBD_PAS_MINI={:g}", sub, policy_.minStep);
  }
  return {};
}

SteppingResult TimeStepper::run(MechanicalState& state, const std::vector<double>& instants,
                                const StepFunction& step, const ConvergedFunction& converged) {
  SteppingResult result;
  std::deque<PendingInstant> pending;
  for (std::size_t i = 1; i < instants.size(); ++i) {
    pending.push_back({instants[i], 0});
  }
  while (!pending.empty()) {
    const PendingInstant target = pending.front();
    if (attempt_) {
      attempt_(state.time, target.time);
    }
    MechanicalState next;
    const StepOutcome o = step(state, target.time, next);
    if (o.converged) {
      pending.pop_front();
      const double startTime = state.time;
      state = std::move(next);
      ++result.computedSteps;
      ConvergedStep c;
      c.index = result.computedSteps;
      c.time = target.time;
      c.startTime = startTime;
      c.level = target.level;
      c.last = pending.empty();
      c.cuts = result.cuts;
      c.outcome = o;
      converged(state, c);
      continue;
    }
    const double length = target.time - state.time;
    const std::string no = refusal(target.level, length);
    if (!no.empty()) {
      log_ << fmt::format("   step INST {:g} -> {:g} failed ({}); no further cut: {}\n", state.time,
                          target.time, failureCause(o), no);
      result.failure = {state.time, target.time, target.level, o, no};
      return result;
    }
    const int n = policy_.subdivisions;
    pending.pop_front();
    for (int k = n; k >= 1; --k) {
      const double t = k == n ? target.time : state.time + length * k / n;
      pending.push_front({t, target.level + 1});
    }
    ++result.cuts;
    log_ << fmt::format("   step INST {:g} -> {:g} failed ({}); step cut into {} sub-steps of {:g} "
                        "(subdivision level {} of SUBD_NIVEAU={})\n",
                        state.time, target.time, failureCause(o), n, length / n, target.level + 1,
                        policy_.maxLevel);
  }
  result.completed = true;
  return result;
}

} // namespace stella
