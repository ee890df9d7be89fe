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

private:
  void factorize(const MechanicalState& start, const Eigen::VectorXd& du, behaviour::Option option,
                 bool first);

  MechanicalSystem& system_;
  NewtonSettings settings_;
  std::ostream& log_;
  bool elasticFactorized_ = false;
  bool checked_ = false;
  double forceScale_ = 0.0; // largest RESI_GLOB_RELA reference of the converged steps
};

} // namespace stella
