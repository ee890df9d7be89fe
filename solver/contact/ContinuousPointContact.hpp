#pragma once
// Continuous contact with contact points that are not slave nodes (DEFI_CONTACT
// FORMULATION='CONTINUE', ZONE/INTEGRATION='GAUSS', 'SIMPSON', 'NCOTES' with ORDRE_INT, and 'AUTO' on
// TRIA6 and QUAD8 slave cells, whose code_aster points are not their nodes; ContinuousIntegrationRule).
// ALGO_CONT='STANDARD' and 'PENALISATION'; Coulomb friction in 2D (D_PLAN, C_PLAN, AXIS) with
// ALGO_CONT='STANDARD' (below); the nodal cases stay with ContinuousContactConstraint.
//
// The unknowns LAGS_C (lambda_i) are on the slave nodes; at each integration point p of a slave
// cell (weight w_p = W_p |J(xi_p)| on the initial configuration, x r_p in AXIS) the multiplier is
// interpolated, lambda_p = sum_i N_i(p) lambda_i, and the point is paired on the master surface
// (orthogonal projection on the master cells of its cell's slave nodes, the master's normal): gap
// g_p, gradient A_p (+N_i(p) n on the slave nodes, -phi_j n on the master nodes). With rho =
// COEF_CONT, point p is in contact (set C) when lambda_p + rho g_p < 0, and the equations are
//   forces      - sum_{p in C} w_p (lambda_p + rho g_p) A_p        on the structure
//   lambda_i      sum_{p in C} w_p N_i(p) g_p - (1/rho) sum_{p not in C} w_p N_i(p) lambda_p = 0.
// Their Newton matrix is symmetric: K + rho sum_C w A^T A (the tangent added here), the coupling
// B = sum_C w_p N(p) A_p and the block -M, M = (1/rho) sum_{not C} w_p N N^T. correct() eliminates
// lambda exactly: (B K^-1 B^T + M) dlambda = G + B ddu - M lambda (G_i = sum_C w N_i g_p), the
// columns of K^-1 B^T through the driver's factorisation, then ddu -= K^-1 B^T dlambda; the
// multipliers of the nodes without a point in contact in their cells are 0 (as in the nodal
// formulation: their block of M alone is singular for some rules). The status
// loop (ALGO_RESO_CONT NEWTON or POINT_FIXE), CONTACT_INIT and ADAPTATION='CYCLAGE' act on the
// points as the nodal formulation acts on the nodes. CONT_NOEU per slave node: RN the nodal contact
// force sum_C w_p N_i(p) (-(lambda_p + rho g_p)), CONT 2 when a point of its cells with N_i != 0 is
// in contact, JEU the node's own gap.
//   ALGO_CONT='PENALISATION' (rho = COEF_PENA_CONT, times the raises of PENE_MAXI / the
// INTERPENETRATION event, shared with the nodal formulation: raisePenalties): lambda_p = rho
// min(g_p, 0) eliminated at each point, point p in contact when g_p < 0, the force -w_p rho g_p A_p
// and the tangent rho w_p A_p^T A_p; the LAGS_C of the nodes of penalised zones are not unknowns:
// stored as the nodal pressure sum_p w_p N_i(p) rho g_p / sum_p w_p N_i(p) (0 where that weight
// is not positive).
//   FROTTEMENT='COULOMB' (ContinuousPointFriction.cpp): the Coulomb law of ContinuousCoulombLaw at
// each point (status 1 stick, 2 slide, 3 slide backwards), with the point's tangent t_p (the
// master's normal turned by +90 degrees), its slip s_p = T_p (u - u_start) (T_p: +N_i(p) t on the
// slave nodes, -phi_j t on the master nodes), its threshold mu t_p (t_p = max(0, -lambda_p):
// the current one with ALGO_RESO_FROT='NEWTON', that of the last friction loop with 'POINT_FIXE').
// ALGO_FROT='STANDARD' (rho_t = COEF_FROT): the unknowns LAGS_F (lambda_t,i, a pressure) on the
// slave nodes, interpolated as LAGS_C, q_p = lambda_t,p + rho_t s_p; the forces -w_p q_p T_p
// (stick, tangent rho_t w_p T_p^T T_p) or -w_p mu t_p e_p T_p (slide, e_p the sense), and the
// equations of lambda_t,i
//   sum_{stick} w_p N_i(p) s_p + (1/rho_t) sum_{others} w_p N_i(p) (mu t_p e_p [slide] - lambda_t,p) = 0.
// ALGO_FROT='PENALISATION' (COEF_PENA_FROT): q_p = q_p,start + rho_t s_p with q_p,start the
// tangential pressure of the point at the start of the step (a history per point); no unknowns.
// With ALGO_RESO_FROT='NEWTON' the sliding force follows LAGS_C: the force column of lambda_i gets
// -sum_{slide} w_p N_i mu e_p T_p and the equation of lambda_t its derivative, so the (dense)
// system of the multipliers is non-symmetric (LU) while the factorised K stays symmetric. correct()
// eliminates every multiplier at once: (B K^-1 C^T + M) dLambda = E + B ddu, M = -dE/dLambda.
// The friction loop (POINT_FIXE) and the RESI_FROT test act as in the nodal formulation (on the
// points' thresholds). CONT_NOEU: CONT 2 when a point of the node's cells slides, 1 when they all
// stick; the tangential nodal force sum_p w_p N_i(p) p_t,p t_p. DEPL LAGS_F1 = lambda_t / (mu
// |LAGS_C|) (PENALISATION: of the nodal tangential pressure). Not implemented yet with points
// (refused): 3D, SANS_GROUP_NO_FR, SEUIL_INIT, GLISSIERE, ALGO_CONT='PENALISATION' with friction.

#include "solver/contact/ContactConstraint.hpp"
#include "solver/contact/ContinuousCoulombLaw.hpp"
#include "solver/fem/Modelling.hpp"
#include "solver/functions/InstantList.hpp"

#include <optional>

namespace stella::contact {

// Whether a resolved zone of a continuous definition integrates at points that are not slave nodes.
bool needsContactPoints(const ContactDefinition& definition);

class ContinuousPointContactConstraint : public ContactConstraint {
public:
  ContinuousPointContactConstraint(std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs,
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
  std::string iterationNote() const override;
  // CONT_NEWT / BOUC_CONT and RESI_GEOM as ContinuousContactConstraint (ContinuousIterationColumns.cpp).
  std::string iterationHeader() const override;

  int contactPoints() const { return static_cast<int>(points_.size()); }
  // DEFI_LIST_INST ECHEC EVENEMENT='INTERPENETRATION' (penalised zones).
  void setInterpenetrationPolicy(std::optional<FailurePolicy> policy) { policy_ = std::move(policy); }

protected:
  std::string resolutionEffects() const override;
  void paired() override;
  std::vector<LinkState> resolvedStates(const Eigen::VectorXd& u) const override;
  bool acceptResolution(const Eigen::VectorXd& u) override;
  void accepted(const std::vector<LinkState>& rowStates) override;

private:
  struct ContactPoint {
    int zone = 0;
    std::vector<int> multiplier; // per node of its slave cell: index of its LAGS_C, -1 excluded
    std::vector<NodeId> nodes;   // the slave cell's nodes
    std::vector<double> shape;   // N_i at the point
    double weight = 0.0;
    double rho = 0.0;       // COEF_CONT, or COEF_PENA_CONT times the zone's raises
    bool penalised = false; // ALGO_CONT='PENALISATION'
    bool paired = false;
    std::vector<std::pair<int, double>> row;           // A_p on the equations
    std::vector<std::pair<int, double>> tangentRow;    // T_p on the equations (friction)
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero(); // t_p
    double gap = 0.0;                                  // at the pairing
  };
  // The equations of the multipliers at (u, ddu) with the statuses (correct()): unknown i is
  // LAGS_C of multiplier i, nm + i its LAGS_F (STANDARD friction).
  struct MultiplierSystem {
    std::vector<std::vector<std::pair<int, double>>> row;    // B
    std::vector<std::vector<std::pair<int, double>>> column; // C - B (NEWTON friction)
    Eigen::MatrixXd mass;                                    // M = -dE/dLambda
    Eigen::VectorXd residual;                                // E + B ddu
    std::vector<char> used;
    bool symmetric = true;
  };
  void normalEquations(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu, const std::vector<char>& status,
                       MultiplierSystem& sys) const;
  void frictionEquations(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                         const std::vector<char>& status, MultiplierSystem& sys) const;
  // The equation of LAGS_F at a point sliding (target mu t_p e_p) or out of contact (target 0).
  void addTangentialMass(const ContactPoint& p, double rho, double target, MultiplierSystem& sys) const;
  bool friction() const { return definition_->hasFriction(); }
  bool frictionUnknowns() const; // STANDARD friction: LAGS_F are unknowns
  bool newtonFriction() const { return friction() && !definition_->settings.continuous.frictionFixedPoint; }
  double coulombOf(const ContactPoint& p) const;
  double thresholdAt(std::size_t q) const;
  Eigen::Vector2d slipAt(const ContactPoint& p, const Eigen::VectorXd& u) const;
  double lambdaTAt(const ContactPoint& p) const;
  CoulombPoint coulombAt(std::size_t q) const;
  // The tangential pressure of point q with status s at u (0 open).
  double tangentialPressureAt(std::size_t q, char s, const Eigen::VectorXd& u) const;
  void addFrictionForces(std::size_t q, char s, const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                         std::vector<Eigen::Triplet<double>>* tangent) const;
  void pairTangent(ContactPoint& p, const std::vector<NodeId>& masterNodes, const std::vector<double>& phi);
  void resetFrictionStep();
  void recordThreshold();
  double frictionCriterion() const;
  bool acceptFriction(const Eigen::VectorXd& u);
  // Per multiplier: the nodal tangential force sum_p w N_i p_t (along t_p, global) and whether a point
  // slides; the nodal tangential pressure (for LAGS_F1 of PENALISATION).
  void nodalFriction(const Eigen::VectorXd& u, const std::vector<char>& status,
                     std::vector<Eigen::Vector3d>& force, std::vector<char>& sliding) const;
  void frictionStates(const Eigen::VectorXd& u, std::vector<LinkState>& states) const;
  void acceptFrictionStep(const Eigen::VectorXd& u);
  void storeFriction(Field& out, std::size_t c0) const;
  bool withFrictionRows() const override { return definition_->hasFriction(); }
  void buildPoints();
  void checkPointCount() const;
  void pairPoints();
  double lambdaAt(const ContactPoint& p) const;
  // The contact pressure at a point in contact: lambda_p + rho g_p, or rho g_p (penalised).
  double pressureAt(const ContactPoint& p, double gap) const;
  // The contact indicator (negative in contact): lambda_p + rho g_p, or g_p (penalised).
  double indicatorAt(const ContactPoint& p, const Eigen::VectorXd& u) const;
  // The penalised zones' PENE_MAXI / INTERPENETRATION control: false when a penalty was raised.
  bool acceptPenetration(const Eigen::VectorXd& u);
  // LAGS_C of the nodes of penalised zones: the nodal pressure of their points (header).
  void penalisedPressures(const Eigen::VectorXd& u);
  double gapAt(const ContactPoint& p, const Eigen::VectorXd& u) const;
  std::vector<char> statusAt(const Eigen::VectorXd& u) const;
  const std::vector<char>& currentStatus(const Eigen::VectorXd& u);
  // Per multiplier: the nodal contact force (positive in compression) and whether a point of its
  // cells with N_i != 0 is in contact.
  void nodalForces(const Eigen::VectorXd& u, std::vector<double>& force, std::vector<char>& touching) const;
  [[noreturn]] void redundant(int multiplier) const;

  fem::Modelling modelling_;
  std::vector<ContactPoint> points_;
  std::vector<NodeId> multiplierNode_;
  std::vector<int> multiplierOfNode_; // per mesh node, -1
  std::vector<double> lambda_;
  std::vector<double> lambdaStart_;
  std::vector<char> status_;       // per point
  std::vector<char> lastStatus_;   // per point, at the last correction
  std::vector<char> contactStart_; // per point, at the last accepted step
  std::vector<int> changes_;
  std::vector<int> frozen_;
  bool useInitial_ = true;
  bool firstStep_ = true;
  int statusIterations_ = 0;
  double noteGeometry_ = -1.0; // geometricCriterion() at the last addForces
  std::string continuation_;
  std::optional<FailurePolicy> policy_; // INTERPENETRATION event
  std::vector<double> penaltyFactor_;   // per zone: the raises of COEF_PENA_CONT
  std::vector<char> penalisedNode_;     // per multiplier: a node of a penalised zone
  std::vector<double> lambdaT_;         // per multiplier: LAGS_F (a pressure along t; STANDARD)
  std::vector<double> lambdaTStart_;    // idem at the start of the step
  std::vector<double> pressureT_;       // per point: the tangential pressure of the last accepted state
  std::vector<double> pressureTStart_;  // per point, at the start of the step (PENALISATION's base)
  std::vector<double> threshold_;       // per point: frozen threshold pressure (POINT_FIXE)
  std::vector<double> lastThreshold_;   // per point: before the last correction (RESI_FROT, NEWTON)
  std::vector<double> lagsFOut_;        // per multiplier: LAGS_F1 of the last accepted state
  int frictionIterations_ = 0;
};

} // namespace stella::contact
