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
//   FROTTEMENT='COULOMB' (ContinuousPointFriction.cpp, D_PLAN, C_PLAN, AXIS and 3D): the Coulomb law of
// ContinuousCoulombLaw at each point (status 1 stick, 2 slide, 3 slide backwards along a single
// friction direction with ALGO_RESO_CONT='POINT_FIXE'), the cone a disc of the tangent plane. The
// point's tangents are a fixed function of its normal n (pointTangents: in 2D n turned by +90
// degrees; in 3D t1 the projection of DX on the tangent plane, of DY when |n_x| > 0.9, t2 = n x t1),
// so that neighbouring points and nodes of a smooth surface share their frame; the point's friction
// directions (rows of its 2 x 2 basis B on t1, t2) are both tangents in 3D, the only one in 2D, or
// what SANS_GROUP_NO_FR / DIRE_EXCL_FROT leave of them at the points of a slave cell with an excluded
// node (ContinuousFrictionExclusion). On direction j: the slip s_p,j = F_p,j (u - u_start) (F_p,j =
// sum_c B_jc T_p,c; T_p,c: +N_i(p) t_c on the slave nodes, -phi_j t_c on the master nodes), the
// threshold mu t_p (t_p = max(0, -lambda_p): the current one with ALGO_RESO_FROT='NEWTON', that of
// the last friction loop with 'POINT_FIXE').
// ALGO_FROT='STANDARD' (rho_t = COEF_FROT): the unknowns LAGS_F (lambda_t,i, a pressure vector of
// components on (t1, t2), one in 2D) on the slave nodes, interpolated as LAGS_C; q_p = B lambda_t,p +
// rho_t s_p. Forces -w_p pi_p . F_p with pi_p = q_p (stick, tangent rho_t w_p F^T F) or mu t_p e_p
// (slide, e_p = q_p / |q_p|; in 3D its turn gives the tangent w_p rho_t alpha F^T P F, alpha = mu t_p
// / |q_p|, P = I - e e^T). The equations of lambda_t,i (components c), per direction j of the point:
//   stick:  sum_p w_p N_i(p) B_jc s_p,j = 0
//   slide and excluded directions: (1/rho_t) sum_p w_p N_i(p) B_jc (target_j - (B lambda_t,p)_j) = 0
// (target mu t_p e_j sliding, 0 along an excluded direction and out of contact), linearised in u
// (3D sliding: the row w_p N_i alpha B^T P F, equal to the force's column: symmetric) and in lambda_t
// (M = (1/rho_t) w N N^T B^T (I - alpha P) B).
// ALGO_FROT='PENALISATION' (COEF_PENA_FROT): q_p = q_p,start + rho_t s_p with q_p,start the
// tangential pressure of the point at the start of the step (a history per point); no unknowns.
// With ALGO_RESO_FROT='NEWTON' the sliding force follows LAGS_C: the force column of lambda_i gets
// -sum_{slide} w_p N_i mu e_p . F_p and the equation of lambda_t its derivative, so the (dense)
// system of the multipliers is non-symmetric (LU) while the factorised K stays symmetric. correct()
// eliminates every multiplier at once: (B K^-1 C^T + M) dLambda = E + B ddu, M = -dE/dLambda.
// The friction loop (POINT_FIXE) and the RESI_FROT test act as in the nodal formulation (on the
// points' thresholds). CONT_NOEU: CONT 2 when a point of the node's cells slides, 1 when they all
// stick; the tangential nodal force sum_p w_p N_i(p) pi_p . F_p. DEPL (LAGS_F1, LAGS_F2) = lambda_t /
// (mu |LAGS_C|) (PENALISATION: of the nodal tangential pressure) on the node's pairing tangents.
//   SEUIL_INIT: LAGS_C = -SEUIL_INIT on the nodes of the points in contact at the first step's start
// (their friction threshold). GLISSIERE='OUI': a point in contact at the start of the calculation
// (CONTACT_INIT) or at the end of an accepted step stays in contact (bilateral). Not implemented yet
// with points (refused): ALGO_CONT='PENALISATION' with friction.

#include "solver/contact/ContactConstraint.hpp"
#include "solver/contact/ContinuousCoulombLaw.hpp"
#include "solver/fem/Modelling.hpp"
#include "solver/functions/InstantList.hpp"

#include <array>
#include <optional>

namespace stella::contact {

// Whether a resolved zone of a continuous definition integrates at points that are not slave nodes.
bool needsContactPoints(const ContactDefinition& definition);

// The row of the DOFs of `terms` (node, coefficient) along the vector v.
std::vector<std::pair<int, double>>
rowAlong(const DofMap& dofs, const std::vector<std::pair<NodeId, double>>& terms, const Point3& v);

// The tangents of a contact point of unit normal n (see the header's comment): 2D t1 = n turned by
// +90 degrees, t2 = 0; 3D t1 the projection of DX (DY when |n_x| > 0.9) on the tangent plane, t2 = n x t1.
void pointTangents(const Point3& n, bool threeD, Point3& t1, Point3& t2);

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
  // For unit tests (ContinuousPointLinearisation.cpp): the multipliers' system at u with the
  // statuses of u, which it sets as an iteration of ALGO_RESO_CONT='NEWTON' does: the residual E,
  // B = dE/du, C = -d forces/dLambda and M = -dE/dLambda over every unknown (LAGS_C, then LAGS_F);
  // the unknowns' values.
  struct Linearisation {
    Eigen::VectorXd residual;
    Eigen::MatrixXd row;
    Eigen::MatrixXd column;
    Eigen::MatrixXd mass;
  };
  Linearisation linearisation(const Eigen::VectorXd& u);
  Eigen::VectorXd multipliers();
  void setMultipliers(const Eigen::VectorXd& values);
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
    CellId cell = 0;             // its slave cell
    std::vector<int> multiplier; // per node of its slave cell: index of its LAGS_C, -1 excluded
    std::vector<NodeId> nodes;   // the slave cell's nodes
    std::vector<double> shape;   // N_i at the point
    double weight = 0.0;
    double rho = 0.0;       // COEF_CONT, or COEF_PENA_CONT times the zone's raises
    bool penalised = false; // ALGO_CONT='PENALISATION'
    bool paired = false;
    std::vector<std::pair<int, double>> row; // A_p on the equations
    // friction: the rows F_p,j along the friction directions (B T_p), the directions in space (B t),
    // the basis B on the tangents (t1, t2) and the number of directions
    std::array<std::vector<std::pair<int, double>>, 2> frictionRow;
    std::array<Eigen::Vector3d, 2> direction{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    Eigen::Matrix2d basis = Eigen::Matrix2d::Identity();
    int directions = 0;
    bool excluded = false; // a node of its slave cell is in SANS_GROUP_NO_FR
    double gap = 0.0;      // at the pairing
  };
  // The equations of the multipliers at (u, ddu) with the statuses (correct()): unknown i is
  // LAGS_C of multiplier i, nm + c i + j component j of its LAGS_F (STANDARD friction, c components).
  struct MultiplierSystem {
    std::vector<std::vector<std::pair<int, double>>> row;    // B
    std::vector<std::vector<std::pair<int, double>>> column; // C - B (NEWTON friction)
    Eigen::MatrixXd mass;                                    // M = -dE/dLambda
    Eigen::VectorXd residual;                                // E + B ddu
    std::vector<char> used;
    bool symmetric = true;
  };
  // The friction equations of one point in its directions' frame (frictionEquations): rows and
  // residuals (w included) and the block of M per pair of shape functions (times w N_k N_l / rho_t).
  struct PointFrictionEquations {
    std::array<std::vector<std::pair<int, double>>, 2> row;
    Eigen::Vector2d residual = Eigen::Vector2d::Zero();
    Eigen::Matrix2d mass = Eigen::Matrix2d::Zero();
    Eigen::Vector2d massResidual = Eigen::Vector2d::Zero(); // target - B lambda_t,p
  };
  // LAGS_C, then LAGS_F (STANDARD friction).
  MultiplierSystem multiplierSystem(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                                    const std::vector<char>& status) const;
  void normalEquations(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu, const std::vector<char>& status,
                       MultiplierSystem& sys) const;
  void frictionEquations(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                         const std::vector<char>& status, MultiplierSystem& sys) const;
  PointFrictionEquations pointFrictionEquations(std::size_t q, char s, const Eigen::VectorXd& u,
                                                const Eigen::VectorXd& ddu) const;
  // NEWTON: the dependence of point q's sliding force and equations on LAGS_C.
  void addSlidingCoupling(std::size_t q, const Eigen::Vector2d& e, MultiplierSystem& sys) const;
  void addPointFrictionEquations(const ContactPoint& p, const PointFrictionEquations& eq, double rho,
                                 bool inContact, MultiplierSystem& sys) const;
  bool friction() const { return definition_->hasFriction(); }
  bool frictionUnknowns() const; // STANDARD friction: LAGS_F are unknowns
  bool newtonFriction() const { return friction() && !definition_->settings.continuous.frictionFixedPoint; }
  int tangentComponents() const { return modelling_ == fem::Modelling::ThreeD ? 2 : 1; }
  // The LAGS_C (i < nm) or LAGS_F component of unknown i of the multipliers' system, and its node.
  double& multiplierValue(Eigen::Index i);
  int multiplierOfUnknown(Eigen::Index i) const;
  double coulombOf(const ContactPoint& p) const;
  double thresholdAt(std::size_t q) const;
  // The slip along the point's friction directions since the step's start.
  Eigen::Vector2d slipAt(const ContactPoint& p, const Eigen::VectorXd& u) const;
  // LAGS_F interpolated at the point, on the tangents (t1, t2).
  Eigen::Vector2d lambdaTAt(const ContactPoint& p) const;
  CoulombPoint coulombAt(std::size_t q) const;
  // The tangential pressure of point q with status s at u along its friction directions (0 open).
  Eigen::Vector2d tangentialPressureAt(std::size_t q, char s, const Eigen::VectorXd& u) const;
  void addFrictionForces(std::size_t q, char s, const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                         std::vector<Eigen::Triplet<double>>* tangent) const;
  // The point's tangents, friction rows and directions at its pairing (normal n; terms: +N_k on the
  // slave nodes, -phi_j on the master nodes).
  void pairFriction(ContactPoint& p, const Point3& n, const std::vector<std::pair<NodeId, double>>& terms);
  void markExcludedPoints();
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
  // SEUIL_INIT and GLISSIERE at the first step's start (ContinuousPointOptions.cpp).
  void applyInitialOptions();
  void holdClosed();
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
  std::optional<FailurePolicy> policy_;         // INTERPENETRATION event
  std::vector<double> penaltyFactor_;           // per zone: the raises of COEF_PENA_CONT
  std::vector<char> penalisedNode_;             // per multiplier: a node of a penalised zone
  std::vector<Eigen::Vector2d> lambdaT_;        // per multiplier: LAGS_F on (t1, t2) (STANDARD)
  std::vector<Eigen::Vector2d> lambdaTStart_;   // idem at the start of the step
  std::vector<Eigen::Vector2d> pressureT_;      // per point: the tangential pressure (on t1, t2) accepted
  std::vector<Eigen::Vector2d> pressureTStart_; // per point, at the start of the step (PENALISATION's base)
  std::vector<char> closed_;                    // per point: held in contact (GLISSIERE)
  std::vector<double> threshold_;               // per point: frozen threshold pressure (POINT_FIXE)
  std::vector<double> lastThreshold_;           // per point: before the last correction (RESI_FROT, NEWTON)
  std::vector<Eigen::Vector3d> lagsFOut_;       // per multiplier: LAGS_F / (mu |LAGS_C|) in space, accepted
  int frictionIterations_ = 0;
};

} // namespace stella::contact
