// TimeStepper: the instants computed when steps longer than a threshold fail, for each rule of
// DEFI_LIST_INST ECHEC (DECOUPE with SUBD_PAS / SUBD_NIVEAU / SUBD_PAS_MINI, ARRET). The
// expected sequences are worked out by hand in the comments.

#include "solver/nonlinear/TimeStepper.hpp"

#include <gtest/gtest.h>
#include <sstream>

namespace stella {
namespace {

// A step "converges" when it is at most `longest` long.
TimeStepper::StepFunction stepsUpTo(double longest) {
  return [longest](const MechanicalState& start, double time, MechanicalState& end) {
    StepOutcome o;
    o.iterations = 1;
    if (time - start.time <= longest + 1.0e-12) {
      o.converged = true;
      end.time = time;
    }
    return o;
  };
}

struct Stepping {
  SteppingResult result;
  std::vector<ConvergedStep> steps;
  std::string log;
};

Stepping stepping(CutPolicy policy, const std::vector<double>& instants, double longest) {
  std::ostringstream log;
  TimeStepper stepper(policy, log);
  MechanicalState state;
  state.time = instants.front();
  Stepping r;
  r.result =
      stepper.run(state, instants, stepsUpTo(longest), [&](const MechanicalState& s, const ConvergedStep& c) {
        EXPECT_EQ(s.time, c.time);
        r.steps.push_back(c);
      });
  r.log = log.str();
  return r;
}

std::vector<double> times(const Stepping& r) {
  std::vector<double> t;
  for (const auto& s : r.steps) {
    t.push_back(s.time);
  }
  return t;
}

TEST(TimeStepper, StepsThatConvergeAreNotCut) {
  const Stepping r = stepping({}, {0.0, 0.25, 0.5}, 0.3);
  EXPECT_TRUE(r.result.completed);
  EXPECT_EQ(r.result.cuts, 0);
  EXPECT_EQ(times(r), (std::vector<double>{0.25, 0.5}));
  EXPECT_FALSE(r.steps[0].last);
  EXPECT_TRUE(r.steps[1].last);
}

TEST(TimeStepper, CutsRecursivelyIntoSubdPasPieces) {
  // 0->1 fails: 0.5, 1 (level 1); 0->0.5 fails: 0.25, 0.5 (level 2); both converge;
  // 0.5->1 fails: 0.75, 1 (level 2); both converge.
  CutPolicy p;
  p.subdivisions = 2;
  const Stepping r = stepping(p, {0.0, 1.0}, 0.3);
  ASSERT_TRUE(r.result.completed);
  EXPECT_EQ(r.result.cuts, 3);
  EXPECT_EQ(times(r), (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    EXPECT_EQ(r.steps[i].level, 2);
    EXPECT_EQ(r.steps[i].index, static_cast<int>(i) + 1);
  }
  EXPECT_TRUE(r.steps.back().last);
  EXPECT_NE(r.log.find("step cut into 2 sub-steps of 0.5 (subdivision level 1 of SUBD_NIVEAU=3)"),
            std::string::npos)
      << r.log;
}

TEST(TimeStepper, LaterInstantsOfTheListKeepLevelZero) {
  // 0->0.4 fails: cut in 4 (0.1 each, level 1); 0.4->0.6 converges at level 0.
  const Stepping r = stepping({}, {0.0, 0.4, 0.6}, 0.3);
  ASSERT_TRUE(r.result.completed);
  ASSERT_EQ(r.steps.size(), 5u);
  EXPECT_NEAR(r.steps[0].time, 0.1, 1e-15);
  EXPECT_EQ(r.steps[3].time, 0.4);
  EXPECT_EQ(r.steps[3].level, 1);
  EXPECT_EQ(r.steps[4].time, 0.6);
  EXPECT_EQ(r.steps[4].level, 0);
}

TEST(TimeStepper, StopsAtSubdNiveau) {
  // SUBD_NIVEAU=1: 0->1 cut once (level 1); 0->0.5 fails and may not be cut again.
  CutPolicy p;
  p.subdivisions = 2;
  p.maxLevel = 1;
  const Stepping r = stepping(p, {0.0, 1.0}, 0.3);
  EXPECT_FALSE(r.result.completed);
  EXPECT_TRUE(r.steps.empty());
  EXPECT_EQ(r.result.failure.startTime, 0.0);
  EXPECT_EQ(r.result.failure.time, 0.5);
  EXPECT_EQ(r.result.failure.level, 1);
  EXPECT_NE(r.result.failure.reason.find("SUBD_NIVEAU=1"), std::string::npos);
}

TEST(TimeStepper, NeverBelowSubdPasMini) {
  // 0->1 cut into 0.5 (0.5 >= 0.3); 0->0.5 fails and 0.25 < SUBD_PAS_MINI=0.3.
  CutPolicy p;
  p.subdivisions = 2;
  p.minStep = 0.3;
  const Stepping r = stepping(p, {0.0, 1.0}, 0.3);
  EXPECT_FALSE(r.result.completed);
  EXPECT_EQ(r.result.cuts, 1);
  EXPECT_EQ(r.result.failure.time, 0.5);
  EXPECT_NE(r.result.failure.reason.find("SUBD_PAS_MINI=0.3"), std::string::npos);
}

TEST(TimeStepper, ArretStopsAtTheFirstFailureKeepingConvergedSteps) {
  CutPolicy p;
  p.subdivide = false;
  const Stepping r = stepping(p, {0.0, 0.2, 0.6}, 0.3);
  EXPECT_FALSE(r.result.completed);
  EXPECT_EQ(times(r), (std::vector<double>{0.2}));
  EXPECT_EQ(r.result.failure.startTime, 0.2);
  EXPECT_EQ(r.result.failure.time, 0.6);
  EXPECT_NE(r.log.find("ACTION='ARRET'"), std::string::npos);
}

// A singular tangent in the iterations (NewtonDriver's StepOutcome::singularTangent) is a failed
// step like a non-converged one: cut, with the cause in the log; the diagnostic (naming the DOF)
// stays in the failure for the final message when no cut is left.
TEST(TimeStepper, SingularTangentInTheIterationsCutsTheStep) {
  std::ostringstream log;
  TimeStepper stepper(CutPolicy{}, log);
  MechanicalState state;
  auto singularWhenLong = [](const MechanicalState& start, double time, MechanicalState& end) {
    StepOutcome o;
    o.iterations = 3;
    if (time - start.time > 0.3) {
      o.singularTangent = Diagnostic::fatal("SOLVE_1", "null pivot on DY of node N7");
      return o;
    }
    o.converged = true;
    end.time = time;
    return o;
  };
  const SteppingResult r = stepper.run(state, {0.0, 1.0}, singularWhenLong, [](const auto&, const auto&) {});
  EXPECT_TRUE(r.completed);
  EXPECT_EQ(r.cuts, 1);          // 1.0 -> 4 sub-steps of 0.25
  EXPECT_EQ(r.computedSteps, 4); // 0.25, 0.5, 0.75, 1.0
  EXPECT_NE(log.str().find("failed (the tangent matrix became singular at iteration 3); step cut into 4"),
            std::string::npos)
      << log.str();

  std::ostringstream log2;
  CutPolicy arret;
  arret.subdivide = false;
  TimeStepper stop(arret, log2);
  MechanicalState start;
  const SteppingResult f = stop.run(start, {0.0, 1.0}, singularWhenLong, [](const auto&, const auto&) {});
  EXPECT_FALSE(f.completed);
  ASSERT_TRUE(f.failure.outcome.singularTangent.has_value());
  EXPECT_EQ(f.failure.outcome.singularTangent->id, "SOLVE_1");
}

} // namespace
} // namespace stella
