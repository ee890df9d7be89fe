#pragma once
// Continuous contact in STAT_NON_LINE (DEFI_CONTACT FORMULATION='CONTINUE', notice §3.1.3, §3.2.3;
// Coulomb friction in 2D, §3.3.3, below): the unknowns LAGS_C (contact pressure, negative in compression,
// code_aster's sign) on the slave nodes, the contact term integrated on the slave cells with their nodes as
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
//   Friction (FROTTEMENT='COULOMB', D_PLAN/C_PLAN/AXIS/3D, ContinuousContactFriction.cpp): the
//   tangential pressure lambda_t of each slave node, a vector of the tangent plane in 3D
//   ((LAGS_F1, LAGS_F2) = lambda_t / (mu |LAGS_C|) on the pairing's tangents), the slip
//   s = T (u - u_start) since the start of the step. The Coulomb cone is a disc: |q| against the
//   threshold, sliding along q / |q| (in 3D with STANDARD the sliding multiplier is a condensed Newton
//   unknown: the consistent tangent of the disc's return map, slidingNewton()). Indicator q = lambda_t
//   + rho_t s (ALGO_FROT='STANDARD', rho_t = COEF_FROT) or lambda_t,start + rho_t s ('PENALISATION',
//   COEF_PENA_FROT: the return mapping of a penalty spring, lambda_t,start that of the step's start);
//   threshold mu |lambda_n| (ALGO_RESO_FROT='NEWTON': the current LAGS_C; 'POINT_FIXE': the LAGS_C of the
//   last friction loop). Stick (|q| < threshold): STANDARD adds the row s = 0 to the Schur complement
//   (tangent rho_t w T1^T T1), PENALISATION the force -w q T1 (same tangent); slip: the force -w sign(q) mu
//   |lambda_n| T1, which with NEWTON depends on lambda_n: the column of that node's normal multiplier becomes
//   A - sign(q) mu T1 and the (small, dense) Schur complement is non-symmetric (LU); the factorised K stays
//   symmetric. CONTACT_INIT: the status of the first step (OUI: every paired node; INTERPENETRE: the nodes
//   with g < 0, within DIST_MAXI when given; NON: none).

#include "solver/contact/ContactConstraint.hpp"
#include "solver/contact/ContinuousCoulombLaw.hpp"
#include "solver/fem/Modelling.hpp"
#include "solver/functions/InstantList.hpp"

#include <optional>

#include <array>

namespace stella::contact {

class ContinuousContactConstraint : public ContactConstraint {
public:
  ContinuousContactConstraint(std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs,
                              fem::Modelling modelling);

  void beginStep(const Eigen::VectorXd& u, double time) override;
  void addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                 std::vector<Eigen::Triplet<double>>* tangent) override;
  // Unsymmetric with friction and ALGO_RESO_GEOM='NEWTON' (the friction's geometric tangent).
  bool symmetric() const override { return !geometricFriction(); }
  void correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
               SaddleSolver& solver) override;
  void store(ResultStep& step) const override;
  std::string singularNote() const override;
  std::string continuationNote() const override;
  // The convergence-table note: nodes in contact, status changes since the last correction (the
  // criterion of the generalised Newton on the status), largest interpenetration.
  std::string iterationNote() const override;
  // The columns the note starts with (ContinuousIterationColumns.cpp), named after code_aster's:
  // CONT_NEWT (ALGO_RESO_CONT='NEWTON': slave nodes whose status changed since the last correction)
  // or BOUC_CONT (POINT_FIXE: status loops so far), RESI_GEOM (the geometric criterion at the row's
  // iterate), and with friction FROT_NEWT / BOUC_FROT (the change of the threshold |LAGS_C| at the
  // last correction, or since the last friction loop, over max |LAGS_C|: what RESI_FROT bounds).
  std::string iterationHeader() const override;
  // DEFI_LIST_INST ECHEC EVENEMENT='INTERPENETRATION' (ContinuousPenetration.cpp).
  void setInterpenetrationPolicy(std::optional<FailurePolicy> policy) { policy_ = std::move(policy); }
  // The factor on COEF_PENA_CONT of each zone (PENE_MAXI of ADAPT_COEF/TOUT, ADAPT_COEF_PENA).
  const std::vector<double>& penaltyFactors() const { return penaltyFactor_; }

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
  [[noreturn]] void redundant(Eigen::Index row) const; // CONTACT_11 naming the row's slave node
  // Frictionless ALGO_RESO_CONT='NEWTON': the correction of the status of the linearised problem,
  // solved exactly from the assembled status (ContinuousLinearisedStatus.cpp).
  void correctWithLinearisedStatus(const Eigen::VectorXd& u, const std::vector<char>& assembled,
                                   Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda, SaddleSolver& solver);
  // Friction (ContinuousContactFriction.cpp). Status codes per link: 0 open, 1 contact (and
  // sticking with friction), 2 sliding (along the direction of the indicator q).
  bool friction() const { return definition_->hasFriction(); }
  const ContinuousZone& zoneOfRow(Eigen::Index row) const;
  double coulombOfRow(Eigen::Index row) const;
  // The slip of each row along its friction directions (rows x 2; the second column zero in 2D).
  Eigen::MatrixXd slipsAt(const Eigen::VectorXd& u) const;
  // The threshold pressure |lambda_n| of link k (NEWTON: current LAGS_C; POINT_FIXE: frozen).
  double thresholdPressure(std::size_t k) const;
  // The Coulomb law's data of a row (ContinuousCoulombLaw.hpp).
  CoulombPoint coulombPoint(Eigen::Index row) const;
  // The indicator q = base + rho_t s (STANDARD: base the multiplier; PENALISATION: the tangential
  // pressure at the start of the step).
  Eigen::Vector2d indicator(Eigen::Index row, const Eigen::Vector2d& slip) const;
  // 0 open, 1 sticking, 2 sliding (along q / |q|), 3 (ALGO_RESO_CONT='POINT_FIXE' only) sliding
  // backwards along the only friction direction of a row that has one (2D, AXIS): the statuses
  // frozen between status loops then also freeze the sliding sense, and a sign change of q is a
  // status change, instead of a force that flips within the Newton iterations (it has no tangent:
  // Newton cycled between the two senses, the step was cut, the penalised stick took another path)
  char frictionStatus(Eigen::Index row, const Eigen::Vector2d& slip) const;
  bool slidingSenseInStatus(Eigen::Index row) const;
  // The unit sliding direction of a row with status s >= 2 (friction directions; zero if none).
  Eigen::Vector2d slidingDirection(Eigen::Index row, char s, const Eigen::Vector2d& slip) const;
  // The tangential pressure of a row in contact with status s at slip `slip` (friction directions).
  Eigen::Vector2d tangentialPressure(Eigen::Index row, char s, const Eigen::Vector2d& slip) const;
  // `position` (ALGO_RESO_GEOM='NEWTON', with a tangent): the positions at u, for the friction's
  // geometric tangent.
  void addFrictionForces(Eigen::Index row, char s, const Eigen::Vector2d& slip, Eigen::VectorXd& forces,
                         std::vector<Eigen::Triplet<double>>* tangent, const NodePosition* position,
                         const Eigen::VectorXd& u) const;
  // The rows of the friction directions (built by frictionPaired: the pairing's tangents, or what
  // SANS_GROUP_NO_FR / DIRE_EXCL_FROT leave of them) and their number per row (0, 1 or 2).
  void frictionPaired();
  const SparseRows& frictionRow(int direction) const {
    return frictionRows_[static_cast<std::size_t>(direction)];
  }
  int frictionDirections(Eigen::Index row) const;
  // The Newton linearisation of a sliding row's multiplier (ALGO_FROT='STANDARD', two friction
  // directions): its equation lambda_t = mu t e, e = q / |q|, q = lambda_t + rho_t s, condensed (the
  // consistent tangent of the disc's return map, ContinuousContactFriction.cpp).
  struct SlidingNewton {
    bool active = false;
    Eigen::Vector2d e = Eigen::Vector2d::Zero(); // the sliding direction q / |q|
    double beta = 0.0;                           // mu t / (|q| - mu t)
    Eigen::Vector2d r = Eigen::Vector2d::Zero(); // lambda_t - mu t e, the equation's residual
  };
  SlidingNewton slidingNewton(Eigen::Index row, char s, const Eigen::Vector2d& slip) const;
  // Before a correction: the linearisation of every row at u (inactive but for STANDARD 3D sliding).
  std::vector<SlidingNewton> slidingLinearisations(const Eigen::VectorXd& u,
                                                   const std::vector<char>& status) const;
  // After a correction ddu at u: the multipliers of the sliding rows (STANDARD) take their Newton
  // update mu t e + beta P (rho_t T ddu - r) (P = I - e e^T) where linearised, otherwise follow the
  // threshold along q / |q| at u + ddu.
  void updateSlidingPressures(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                              const std::vector<char>& status, const std::vector<SlidingNewton>& newton);
  // LinkState friction and slip (pairing tangents) of a row, and back.
  void frictionState(Eigen::Index row, char s, const Eigen::Vector2d& slip, LinkState& state) const;
  void acceptFrictionState(Eigen::Index row, const LinkState& state);
  // SEUIL_INIT: the contact pressure of the nodes in contact at the first step's start.
  void applyInitialThreshold();
  // GLISSIERE='OUI': a link held closed (bilateral) once in contact.
  bool heldClosed(std::size_t k) const;
  void storeFriction(Field& out, std::size_t c0) const;
  // The friction loop of POINT_FIXE and the RESI_FROT test: false while the threshold moves.
  bool acceptFriction(const Eigen::VectorXd& u);
  void resetFrictionStep();
  void recordThreshold(); // |LAGS_C| before a correction (the RESI_FROT test of NEWTON)
  // The RESI_FROT criterion: the change of |LAGS_C| against the threshold it is compared with, over
  // max |LAGS_C| (infinite when they all vanished, 0 when nothing changed); negative before any correction.
  double frictionCriterion() const;
  bool withFrictionRows() const override { return definition_->hasFriction(); }
  // ALGO_RESO_GEOM='NEWTON' (ContinuousGeometricTangent.cpp): the pairing follows the Newton iterates
  // (pairInNewton pairs again at u when it moved, noting the change since the last pairing for
  // RESI_GEOM; with POINT_FIXE it only notes the criterion), and the tangent gets the second
  // derivative of the gap of row `row` times `coefficient` (w times the contact pressure).
  bool geometryNewton() const;
  void pairInNewton(const Eigen::VectorXd& u);
  // False (continuation note set) while NEWTON's geometric criterion exceeds RESI_GEOM.
  bool geometryConverged();
  void addGeometricTangent(Eigen::Index row, double coefficient, const NodePosition& position,
                           std::vector<Eigen::Triplet<double>>& tangent) const;
  // Friction with ALGO_RESO_GEOM='NEWTON' (ContinuousGeometricFriction.cpp): M_j = dT_j / dx of a
  // row's friction directions over its nodes (local (node, component) order, the slave first;
  // `dofs` -1 where a component has no DOF) and v = u - u_start there.
  bool geometricFriction() const;
  struct RowGeometry {
    std::vector<int> dofs;
    std::array<Eigen::MatrixXd, 2> m;
    Eigen::VectorXd v;
  };
  RowGeometry rowGeometry(Eigen::Index row, const NodePosition& position, const Eigen::VectorXd& u) const;
  // w dp/ds T (T + G)^T beyond c T T^T, and w p_j M_j (c = w dp/ds, p the tangential pressure).
  void addGeometricFrictionTangent(Eigen::Index row, const Eigen::Vector2d& pressure,
                                   const Eigen::Matrix2d& c, const NodePosition& position,
                                   const Eigen::VectorXd& u,
                                   std::vector<Eigen::Triplet<double>>& tangent) const;
  // The linearised slip rows T_j + G_j at u (slipRows_), and the row of direction j to linearise
  // the slip with: those, or the friction rows without ALGO_RESO_GEOM='NEWTON'.
  void linearisedSlipRowsAt(const Eigen::VectorXd& u);
  const SparseRows& slipRow(int direction) const;
  // The interpenetration of the penalised zones against PENE_MAXI (ADAPT_COEF/TOUT) and the
  // INTERPENETRATION event: false when a penalty was raised (ContinuousPenetration.cpp).
  bool acceptPenetration(const Eigen::VectorXd& u);
  double penaltyFactor(int zone) const;
  std::string penetrationEffects() const;

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
  std::vector<Eigen::Vector2d> lagsF_;      // per link: tangential pressure along the friction directions
  std::vector<Eigen::Vector2d> lagsFStart_; // per link, at the start of the step
  std::array<SparseRows, 2> frictionRows_;  // per row: the friction directions
  std::vector<Eigen::Matrix2d> basis_; // per row: friction direction j = basis(j, :) (tangent1, tangent2)
  std::vector<int> directions_;        // per row: number of friction directions
  std::vector<char> closed_;           // per link: held closed (GLISSIERE='OUI')
  std::vector<double> threshold_;      // per link: frozen threshold pressure (POINT_FIXE)
  std::vector<double> lastThreshold_;  // per link: |LAGS_C| at the previous correction (RESI_FROT)
  int frictionIterations_ = 0;
  double noteGeometry_ = -1.0;          // geometricCriterion() at the last addForces
  std::array<SparseRows, 2> slipRows_;  // linearisedSlipRowsAt
  std::optional<FailurePolicy> policy_; // INTERPENETRATION event
  std::vector<double> penaltyFactor_;   // per zone: the raises of COEF_PENA_CONT
};

} // namespace stella::contact
