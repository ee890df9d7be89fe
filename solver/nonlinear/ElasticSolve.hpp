#pragma once
// The linear static solve of MECA_STATIQUE on a MechanicalSystem: K u = F with the dualised
// relations and eliminated DOFs, the elastic matrix factorised once and reused for every instant.

#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/nonlinear/PointState.hpp"

namespace stella {

struct StaticSolution {
  Eigen::VectorXd displacement; // physical size
  Eigen::VectorXd multipliers;  // one per relation (force units)
  PointState state;             // stresses at the Gauss points
};

class ElasticSolve {
public:
  explicit ElasticSolve(MechanicalSystem& system) : system_(system) {}
  // Solves at `time` (factorises on the first call). `withStress` integrates SIEF_ELGA.
  StaticSolution solve(double time, bool withStress);

private:
  MechanicalSystem& system_;
  bool factorized_ = false;
};

} // namespace stella
