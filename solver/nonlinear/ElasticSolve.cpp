// ElasticSolve: one factorisation of the elastic stiffness, one solve per instant.

#include "solver/nonlinear/ElasticSolve.hpp"

#include <optional>

namespace stella {

StaticSolution ElasticSolve::solve(double time, bool withStress) {
  const int n = system_.dofs().physicalCount();
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(n);
  std::optional<PointState> zero;
  if (!factorized_) {
    StiffnessMatrix& k = system_.stiffness(true); // the pattern, at the first call: numbering
    {
      PhaseClock clock(system_.phases().assembly);
      zero = zeroPointState(system_.model(), system_.behaviours().maxInternalVariables());
      system_.assembler().run(none, none, *zero, behaviour::Option::ElasticTangent,
                              {nullptr, nullptr, nullptr, &k});
    }
    system_.solver().factorize(k);
    factorized_ = true;
  }
  Eigen::VectorXd f;
  Eigen::VectorXd g;
  Eigen::VectorXd p;
  {
    PhaseClock clock(system_.phases().assembly);
    f = system_.externalForces(time);
    g = system_.relationValues(time);
    p = system_.eliminatedValues(time);
  }
  StaticSolution s;
  system_.solver().solve(f, g, p, s.displacement, s.multipliers);
  PhaseClock clock(system_.phases().post);
  if (!zero) {
    zero = zeroPointState(system_.model(), system_.behaviours().maxInternalVariables());
  }
  s.state = *zero;
  if (withStress) {
    system_.assembler().run(none, s.displacement, *zero, behaviour::Option::Full,
                            {nullptr, nullptr, &s.state});
  }
  return s;
}

} // namespace stella
