#pragma once
// Continuous contact in STAT_NON_LINE (DEFI_CONTACT FORMULATION='CONTINUE', frictionless, notice
// §3.1.3, §3.2.3): the unknowns LAGS_C (contact pressure, negative in compression, code_aster's
// sign) on the slave nodes, the contact term integrated on the slave cells with their nodes as
// integration points (INTEGRATION='AUTO', "méthode des noeuds": node i weighs
// w_i = W_i |J(xi_i)| (x r_i in AXIS, per radian), W_i the Newton-Cotes weight of the reference
// cell; J on the initial configuration, as the small-strain stresses), each node paired on the master surface
// (node-to-surface, the discrete formulation's pairing and geometric loop).
//
//   ALGO_CONT='STANDARD' (augmented Lagrangian, rho = COEF_CONT): node i is in contact when
//   lambda_i + rho g_i < 0 (g the gap, positive when open). The equations of the unknowns
//   (u, lambda) are
//     contact:     force -w (lambda + rho g) grad g on the structure,   w g = 0
//     no contact:  no force,                                          -(w / rho) lambda = 0
//   and their Newton matrix is symmetric:
//     [ K + rho w A^T A (contact)   w A^T (contact)         ] [du     ]   [r_u     ]
//     [ w A (contact)               -w/rho (no contact)     ] [dlambda] = [r_lambda]
//   (A the gradient of the gap). The driver factorises K + rho w A^T A (the tangent this class
//   adds) and solves with it; correct() eliminates the multipliers exactly: the non-contact ones
//   vanish, the contact ones solve the Schur complement S = A_c K^-1 A_c^T (columns through the
//   same factorisation, NB_RESOL-free: one backend call for all). The symmetric storage and
//   factorisation of the driver are kept.
//   ALGO_CONT='PENALISATION' (COEF_PENA_CONT = rho): lambda = rho min(g, 0), eliminated
//   exactly from its own equation (its block -w/rho is regular): the force -w rho g grad g and
//   the tangent rho w A^T A of the nodes in contact.
//   ALGO_RESO_CONT='NEWTON': the status is re-evaluated at every Newton iteration from the
//   current (u, lambda) (generalised Newton); a step converges when the status no longer changes.
//   'POINT_FIXE': the status is frozen during the Newton iterations and re-evaluated at their
//   convergence (at most ITER_CONT_MAXI, or ITER_CONT_MULT x slave nodes, status loops).
//   CONTACT_INIT: the status of the first step (OUI: every paired node; INTERPENETRE: the nodes
//   with g < 0, within DIST_MAXI when given; NON: none).

#include "solver/contact/ContactConstraint.hpp"
#include "solver/fem/Modelling.hpp"

namespace stella::contact {

class ContinuousContactConstraint : public ContactConstraint {
public:
  ContinuousContactConstraint(std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs,
                              fem::Modelling modelling);

  void beginStep(const Eigen::VectorXd& u, double time) override;
  void addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                 std::vector<Eigen::Triplet<double>>* tangent) override;
  bool symmetric() const override { return true; }
  void correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
               SaddleSolver& solver) override;
  void store(ResultStep& step) const override;
  std::string singularNote() const override;
  std::string continuationNote() const override;
  // The convergence-table note: nodes in contact, status changes since the last correction (the
  // criterion of the generalised Newton on the status), largest interpenetration.
  std::string iterationNote() const override;

  // LAGS_C of each link (slave node) of the pairing: the contact pressure, negative in
  // compression; and its integration weight w.
  const std::vector<double>& pressures() const { return lagsC_; }
  const std::vector<double>& weights() const { return weightLink_; }
  int statusIterations() const { return statusIterations_; }

protected:
  std::string resolutionEffects() const override;
  void paired() override;
  std::vector<LinkState> resolvedStates(const Eigen::VectorXd& u) const override;
  bool acceptResolution(const Eigen::VectorXd& u) override;
  void accepted(const std::vector<LinkState>& rowStates) override;

private:
  bool penalised(Eigen::Index row) const;
  bool cycleTreatment(int zone) const;
  // The status of each row at (u, LAGS_C): 1 in contact.
  std::vector<char> statusAt(const Eigen::VectorXd& u) const;
  // The status used now: re-evaluated (NEWTON) or frozen (POINT_FIXE).
  const std::vector<char>& currentStatus(const Eigen::VectorXd& u);
  void computeWeights();

  fem::Modelling modelling_;
  Eigen::VectorXd weight_;         // per row
  Eigen::VectorXd coefficient_;    // per row: COEF_CONT or COEF_PENA_CONT
  std::vector<char> status_;       // per link, the status of the last evaluation
  std::vector<char> lastStatus_;   // per link, the status of the last correction
  bool useInitial_ = true;         // the step's initial status until the first correction
  std::vector<double> lagsC_;      // per link
  std::vector<double> lagsCStart_; // per link, at the start of the step
  std::vector<char> contactLink_;  // per link: in contact at the last accepted step
  std::vector<double> weightLink_; // per link
  bool firstStep_ = true;
  int statusIterations_ = 0;
  std::vector<int> changes_; // per link: status changes in the step
  std::vector<int> frozen_;  // per link: -1, or the status frozen by CYCLAGE
  std::string continuation_;
};

} // namespace stella::contact
