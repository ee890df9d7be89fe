#pragma once
// The Newton loop of STAT_NON_LINE for one step: a prediction (PREDICTION='TANGENTE' or
// 'ELASTIQUE': a solve with the tangent at the start of the step or the elastic matrix;
// 'EXTRAPOLE': the last step's increment scaled by the ratio of the step lengths; 'DEPL_CALCULE':
// the displacement of a given result at the new time), then corrections until the global
// residual criteria hold (RESI_GLOB_RELA relative to the external forces and reactions,
// RESI_GLOB_MAXI absolute; combined as CONVERGENCE/VERIF says), printing code_aster's convergence
// table (with the SUIVI_DDL columns of setIterationColumns) to the stream it is given.
// MATR_RIGI_SYME='OUI' factorises the symmetric part of an unsymmetric tangent.
// The tangent is reassembled every REAC_ITER iterations and, at the prediction, every REAC_INCR
// steps (MATRICE='TANGENTE'), or never (MATRICE='ELASTIQUE': the elastic matrix factorised once).
// With RECH_LINEAIRE each correction is scaled by the secant line search (CORDE). Step cutting on
// failure is left to the caller (TimeStepper).

#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/nonlinear/ConvergenceVerif.hpp"
#include "solver/nonlinear/IterationColumns.hpp"
#include "solver/nonlinear/PointState.hpp"
#include "solver/nonlinear/StepConstraint.hpp"

#include <functional>
#include <optional>
#include <ostream>
#include <string>

namespace stella {

// RECH_LINEAIRE METHODE='CORDE': secant iterations on the residual projected on the correction.
struct LineSearchSettings {
  bool enabled = false;
  int maxIterations = 3;         // ITER_LINE_MAXI
  double relativeResidual = 0.1; // RESI_LINE_RELA
  double rhoMin = 0.01;          // RHO_MIN
  double rhoMax = 10.0;          // RHO_MAX
  double rhoExcluded = 0.009;    // RHO_EXCL
};

enum class Prediction { Tangent, Elastic, Extrapolated, Computed };

struct NewtonSettings {
  bool tangentMatrix = true; // MATRICE='TANGENTE'
  int reacIter = 1;          // REAC_ITER (0: only at the prediction)
  int reacIncr = 1;          // REAC_INCR (0: the prediction matrix of the first step only)
  Prediction prediction = Prediction::Tangent;
  double resiGlobRela = 1.0e-6; // RESI_GLOB_RELA (<= 0: not used)
  double resiGlobMaxi = -1.0;   // RESI_GLOB_MAXI (<= 0: not used)
  int iterGlobMaxi = 10;        // ITER_GLOB_MAXI (ITER_GLOB_ELAS with MATRICE='ELASTIQUE')
  CriteriaCombination verif = CriteriaCombination::All; // CONVERGENCE/VERIF
  bool symmetrizeTangent = false; // NEWTON/MATR_RIGI_SYME='OUI': (K + K^T) / 2, factorised symmetric
  LineSearchSettings lineSearch;  // RECH_LINEAIRE
  // PREDICTION='DEPL_CALCULE': the displacement (physical size) of NEWTON/EVOL_NOLI at a time.
  std::function<Eigen::VectorXd(double)> computedDisplacement;
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
  // The tangent matrix of a correction iteration was singular (SOLVE_1, naming the DOF): the
  // state reached by the iterations, not the model, is at fault, so the step may be cut
  // (code_aster's EVENEMENT='ERREUR' includes a singular matrix). A singular matrix in the
  // prediction (the converged state's) is an error at once: a shorter step cannot change it.
  std::optional<Diagnostic> singularTangent;
  int iterations = 0;
  int lineSearchIterations = 0; // over the whole step
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
  // Extra columns of the convergence table (SUIVI_DDL), or none. Not owned.
  void setIterationColumns(const IterationColumns* columns) { columns_ = columns; }

  // Converged steps so far (REAC_INCR counts them).
  int convergedSteps() const { return convergedSteps_; }
  // Factorisations asked of the solver so far, as symmetric and as unsymmetric matrices.
  int symmetricFactorisations() const { return symmetricFactorisations_; }
  int unsymmetricFactorisations() const { return unsymmetricFactorisations_; }

private:
  // The prediction of a step: the increment `du` and multipliers `lambda`; returns the matrix
  // note of the table ("TANGENTE", "ELASTIQUE" or "" when the factorisation is kept).
  std::string predict(const MechanicalState& start, double time, const Eigen::VectorXd& fext,
                      const Eigen::VectorXd& g, const Eigen::VectorXd& imposed, Eigen::VectorXd& du,
                      Eigen::VectorXd& lambda);
  // Whether the prediction reassembles its matrix (REAC_INCR).
  bool predictionMatrixDue() const;
  // Residual F_ext - F_int(u + du) - C^T lambda + constraint forces, zero on eliminated DOFs;
  // `fint` receives F_int. Returns the behaviour's status.
  AssemblyStatus residual(const MechanicalState& start, const Eigen::VectorXd& du,
                          const Eigen::VectorXd& lambda, const Eigen::VectorXd& fext,
                          behaviour::Option option, AssemblyOutput out, Eigen::VectorXd& r);
  // RECH_LINEAIRE CORDE: the step length rho along `ddu` (1 without line search).
  double lineSearch(const MechanicalState& start, const Eigen::VectorXd& du, const Eigen::VectorXd& ddu,
                    const Eigen::VectorXd& lambda, const Eigen::VectorXd& fext, const Eigen::VectorXd& r0,
                    int& iterations);
  void factorize(const MechanicalState& start, const Eigen::VectorXd& du, behaviour::Option option,
                 bool first);
  // Factorises K (+ the constraint's tangent terms), adding the constraint's note to a
  // singular-stiffness error.
  void factorizeMatrix(StiffnessMatrix& k, const Eigen::VectorXd& u);
  // The constraint's forces at u (zero without a constraint).
  Eigen::VectorXd constraintForces(const Eigen::VectorXd& u);
  bool symmetric() const;
  // Runs a call of the constraint, adding its time to the contact phase without the linear
  // solutions it asks (those stay in the solver's phases).
  template <class Call> decltype(auto) timedConstraint(Call&& call);
  double solverSeconds() const;

  MechanicalSystem& system_;
  NewtonSettings settings_;
  std::ostream& log_;
  StepConstraint* constraint_ = nullptr;
  const IterationColumns* columns_ = nullptr;
  bool elasticFactorized_ = false;
  double forceScale_ = 0.0; // RESI_GLOB_RELA reference of the last step converged under load
  // The forces of the current step so far: the new loads and the constraint's forces at the
  // step start, then each iteration's reference (judges when a reference has vanished).
  double stepScale_ = 0.0;
  // max |K_ii| of the structure's last factorised tangent: with the largest |u|, the scale of the
  // round-off of the internal forces (relativeTest in NewtonDriver.cpp).
  double stiffnessScale_ = 0.0;
  // The RESI_GLOB_RELA reference of an iteration: the largest of |F_ext - reactions| on the free
  // DOFs, |F_int| on the eliminated ones and |constraint forces| on every DOF, each apart, so that
  // a contact force and the reaction of the fixed node it acts on do not cancel.
  double residualReference(const Eigen::VectorXd& fext, const Eigen::VectorXd& reactions,
                           const Eigen::VectorXd& fint, const Eigen::VectorXd& forces) const;
  int convergedSteps_ = 0;
  int symmetricFactorisations_ = 0;
  int unsymmetricFactorisations_ = 0;
  bool factorized_ = false;
  Eigen::VectorXd lastIncrement_; // of the last converged step (EXTRAPOLE)
  Eigen::VectorXd lastMultiplierIncrement_;
  double lastStepLength_ = 0.0;
};

} // namespace stella
