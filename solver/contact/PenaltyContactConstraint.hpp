#pragma once
// Penalised discrete contact in STAT_NON_LINE (ALGO_CONT='PENALISATION' with E_N, notice
// §3.2.2) and penalised Coulomb friction (FROTTEMENT='COULOMB', ALGO_FROT='PENALISATION' with
// E_T, COULOMB, COEF_MATR_FROT, §3.3.2): the contact forces and their tangent enter Newton's
// residual and matrix (the tangent E_N A_i^T A_i of the links active at the iterate: the matrix
// is K modified by the penalties, as the notice's Figure 3.1.2-1 says); after each linear solve
// the links open at the iterate that the solve would push through the master are resolved on
// their condensed rows, with the compliance 1/E_N on the diagonal of their Schur complement
// (correct(): the penalised law as a regularised dual problem, CONTRAINTE's active-set method).
// Without it a link open in one iterate penetrates in the next by what the structure alone
// would move it, and with E_N >> the structure's stiffness Newton cycles between active sets.
// Friction is incremental: the slip of a step is measured from the displacement at the step
// start, and the elastic slip -t/E_T of the last accepted step carries the friction force over
// (a return mapping on the tangential force). The friction tangent of sliding links is
// unsymmetric: the driver then factorises with unsymmetric storage. COEF_MATR_FROT weighs it
// while RESI_GLOB_RELA >= 1e-3 (0, the default, leaves it out: the matrix stays symmetric far
// from the solution); below 1e-3 the whole tangent is used whatever COEF_MATR_FROT, as code_aster
// does, so that the last iterations converge quadratically instead of by the fixed point of the
// friction forces on the normal forces (linear, factor about COULOMB: SNL_3 at E_N >= 1e10).
// DEFI_LIST_INST ECHEC EVENEMENT='INTERPENETRATION': above PENE_MAXI, ADAPT_COEF_PENA multiplies
// E_N by 10 (at most COEF_MAXI) and Newton goes on; ARRET stops the analysis.

#include "solver/contact/ContactConstraint.hpp"
#include "solver/functions/InstantList.hpp"

#include <optional>

namespace stella::contact {

class PenaltyContactConstraint : public ContactConstraint {
public:
  PenaltyContactConstraint(std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs,
                           std::optional<FailurePolicy> interpenetration);

  void beginStep(const Eigen::VectorXd& u, double time) override;
  void addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                 std::vector<Eigen::Triplet<double>>* tangent) override;
  bool symmetric() const override { return symmetric_; }
  void residualMeasured(double relativeResidual) override;
  void correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
               SaddleSolver& solver) override;

  std::string noConvergenceNote() const override;

  // The current factor on E_N (ADAPT_COEF_PENA).
  double penaltyFactor() const { return factor_; }

protected:
  std::string resolutionEffects() const override;
  void paired() override;
  std::vector<LinkState> resolvedStates(const Eigen::VectorXd& u) const override;
  bool acceptResolution(const Eigen::VectorXd& u) override;
  void accepted(const std::vector<LinkState>& rowStates) override;
  bool withFrictionRows() const override { return friction_; }
  std::string singularCause() const override;

private:
  PenaltyEvaluation evaluate(const Eigen::VectorXd& u) const;
  void updateParameters();
  // COEF_MATR_FROT per row, or 1 once RESI_GLOB_RELA < 1e-3 or the statuses settled.
  void applyMatrixCoefficients();
  void addPatternOfOpenLinks(const PenaltyEvaluation& e, std::vector<Eigen::Triplet<double>>& tangent) const;

  bool friction_ = false;
  std::optional<FailurePolicy> policy_;
  double factor_ = 1.0;
  bool symmetric_ = true;
  bool residualBelowThreshold_ = false;         // the last RESI_GLOB_RELA of the step was below 1e-3
  bool statusesSettled_ = false;                // the statuses of the iterate are the last tangent's
  std::vector<LinkStatus> lastTangentStatuses_; // of the last tangent of the step
  PenaltyParameters parameters_;                // per row of the current pairing
  std::vector<Point3> elasticSlip_;             // per link: -t/E_T of the last accepted step
  // Per row: the link penetrated at an iterate of the current step. Only such a link, open again
  // and pushed through by the next solve, is resolved on the condensed rows (the cycling the
  // condensation cures needs a link to have been closed once); a link closing for the first time
  // takes the penalised law at the next iterate as in plain Newton, so a surface of 10^4 links
  // closing at once costs no dense Schur complement.
  std::vector<char> closedThisStep_;
};

} // namespace stella::contact
