#pragma once
// The Newton loop of STAT_NON_LINE over the instants of a list: for each step, a prediction
// (tangent at the start of the step, or the elastic matrix), then corrections until the global
// residual criteria hold (RESI_GLOB_RELA relative to the external forces and reactions,
// RESI_GLOB_MAXI absolute), printing code_aster's convergence table in the message file.
// The tangent is reassembled every REAC_ITER iterations (MATRICE='TANGENTE') or never
// (MATRICE='ELASTIQUE': the elastic matrix factorised once). Step cutting on failure is left to
// the caller.

#include "solver/nonlinear/MechanicalSystem.hpp"
#include "solver/nonlinear/PointState.hpp"
#include "solver/nonlinear/StepConstraint.hpp"

#include <ostream>
#include <string>

namespace stella {

struct NewtonSettings {
  bool tangentMatrix = true;      // MATRICE='TANGENTE'
  int reacIter = 1;               // REAC_ITER (0: only at the prediction)
  bool elasticPrediction = false; // PREDICTION='ELASTIQUE'
  double resiGlobRela = 1.0e-6;   // RESI_GLOB_RELA (<= 0: not used)
  double resiGlobMaxi = -1.0;     // RESI_GLOB_MAXI (<= 0: not used)
  int iterGlobMaxi = 10;          // ITER_GLOB_MAXI
};

// The converged state at a time.
struct MechanicalState {
  double time = 0.0;
  Eigen::VectorXd displacement; // physical size
  Eigen::VectorXd multipliers;  // one per relation
  PointState points;
};

struct StepOutcome {
  bool converged = false;
  bool integrationFailed = false; // a behaviour failed at a Gauss point
  int iterations = 0;
  double resiRela = 0.0;
  double resiMaxi = 0.0;
};

class NewtonDriver {
public:
  NewtonDriver(MechanicalSystem& system, NewtonSettings settings, std::ostream& log);

  MechanicalState initialState(double time) const;
  // One step from `start` to `time`; on convergence `end` holds the new state.
  StepOutcome step(const MechanicalState& start, double time, MechanicalState& end);

  // A condition solved with the mechanical equations (contact), or none (the default: nothing
  // of it is called). Not owned.
  void setConstraint(StepConstraint* constraint) { constraint_ = constraint; }

private:
  void factorize(const MechanicalState& start, const Eigen::VectorXd& du, behaviour::Option option,
                 bool first);
  // Factorises K (+ the constraint's tangent terms), adding the constraint's note to a
  // singular-stiffness error.
  void factorizeMatrix(std::vector<Eigen::Triplet<double>>& triplets, const Eigen::VectorXd& u, bool check);
  // The constraint's forces at u (zero without a constraint).
  Eigen::VectorXd constraintForces(const Eigen::VectorXd& u);
  bool symmetric() const;

  MechanicalSystem& system_;
  NewtonSettings settings_;
  std::ostream& log_;
  StepConstraint* constraint_ = nullptr;
  bool elasticFactorized_ = false;
  bool checked_ = false;
  double forceScale_ = 0.0; // largest RESI_GLOB_RELA reference of the converged steps
};

} // namespace stella
