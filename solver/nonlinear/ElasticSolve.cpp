// ElasticSolve: one factorisation of the elastic stiffness, one solve per instant.

#include "solver/nonlinear/ElasticSolve.hpp"

namespace stella {

StaticSolution ElasticSolve::solve(double time, bool withStress) {
  const int n = system_.dofs().physicalCount();
  const PointState zero = zeroPointState(system_.model(), system_.behaviours().maxInternalVariables());
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(n);
  if (!factorized_) {
    StiffnessMatrix* k = nullptr;
    {
      PhaseClock clock(system_.phases().assembly);
      k = &system_.stiffness(true);
      system_.assembler().run(none, none, zero, behaviour::Option::ElasticTangent,
                              {nullptr, nullptr, nullptr, k});
    }
    system_.solver().factorize(*k);
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
  s.state = zero;
  if (withStress) {
    PhaseClock clock(system_.phases().post);
    system_.assembler().run(none, s.displacement, zero, behaviour::Option::Full,
                            {nullptr, nullptr, &s.state});
  }
  return s;
}

} // namespace stella
