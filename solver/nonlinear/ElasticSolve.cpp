// ElasticSolve: one factorisation of the elastic stiffness, one solve per instant.

#include "solver/nonlinear/ElasticSolve.hpp"

namespace stella {

StaticSolution ElasticSolve::solve(double time, bool withStress) {
  const int n = system_.dofs().physicalCount();
  const PointState zero = zeroPointState(system_.model(), system_.behaviours().maxInternalVariables());
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(n);
  if (!factorized_) {
    std::vector<Eigen::Triplet<double>> triplets;
    system_.assembler().run(none, none, zero, behaviour::Option::ElasticTangent,
                            {&triplets, nullptr, nullptr});
    system_.solver().factorize(system_.matrix(triplets), true);
    factorized_ = true;
  }
  StaticSolution s;
  system_.solver().solve(system_.externalForces(time), system_.relationValues(time),
                         system_.eliminatedValues(time), s.displacement, s.multipliers);
  s.state = zero;
  if (withStress) {
    system_.assembler().run(none, s.displacement, zero, behaviour::Option::Full,
                            {nullptr, nullptr, &s.state});
  }
  return s;
}

} // namespace stella
