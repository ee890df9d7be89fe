#pragma once
// LAC (mortar, "Local Average Contact") contact in STAT_NON_LINE: DEFI_CONTACT
// FORMULATION='CONTINUE', ZONE=_F(ALGO_CONT='LAC', APPARIEMENT='MORTAR', ...), notice §3.1.4, 2D
// models (D_PLAN, C_PLAN, AXIS) and 3D (LacPairing3d.cpp). The slave surface is cut into patches by
// CREA_MAILLAGE/DECOUPE_LAC (Mesh::lacPatches()); each patch P carries ONE contact pressure
// lambda_P (LAGS_C, negative in compression) and one condition on its mean gap
// g_P = G_P / L_P (LacPairing.hpp: the gap integrated over the exact slave/master overlaps).
//
// The equations are those of the continuous formulation's augmented Lagrangian
// (ContinuousContactConstraint.hpp) with the patch as the contact point and w = L_P:
//   contact (lambda_P + rho g_P < 0):  force -(lambda_P + rho g_P) dG_P,  g_P = 0
//   no contact:                         no force,                         lambda_P = 0
// rho = 100 (the catalogue gives LAC no COEF_CONT; the converged state does not depend on rho,
// it only chooses the status indicator and stiffens the matrix of a body held by contact).
// The driver factorises K + rho/L_P dG_P dG_P^T (patches in contact); correct() eliminates the
// multipliers exactly by the Schur complement of the patches in contact.
//
// Status (ALGO_RESO_CONT): NEWTON re-evaluates it at every Newton iteration (generalised Newton),
// POINT_FIXE at the convergence of the Newton iterations; a step ends when it no longer changes.
// Geometry (ALGO_RESO_GEOM): NEWTON pairs again at every Newton iteration on the current
// positions (the overlaps, normals and gaps follow the iterate) and a step ends when the contact
// nodes moved by less than RESI_GEOM x the step's displacement since the last pairing; in 2D the
// tangent is the consistent linearisation of the mortar integrals (overlap ends, normals, master
// points, Jacobians: LacGeometricTangent.cpp; non-symmetric), in 3D it holds them fixed (a
// quasi-Newton on geometry, exact for flat surfaces in contact);
// POINT_FIXE pairs at the start of each step and again at convergence (REAC_GEOM AUTOMATIQUE with
// ITER_GEOM_MAXI and RESI_GEOM, CONTROLE with NB_ITER_GEOM, SANS: the initial pairing only).
// CONTACT_INIT: the status of the first step (OUI every paired patch, INTERPENETRE the patches
// with g_P < 0, NON none).
// Fields: LAGS_C in DEPL on one node per patch (the node shared by the most of its slave cells:
// the centre of a 3D fan, the middle of an edge cut in two; the middle node of a SEG3 patch), and
// CONT_ELEM (mortar/ContElemField.hpp). No CONT_NOEU (code_aster writes none for LAC).
// Friction (FROTTEMENT='COULOMB', 2D and 3D, beyond code_aster): LacFriction.cpp.

#include "solver/contact/ContactDefinition.hpp"
#include "solver/contact/lac/LacPairing.hpp"
#include "solver/database/Field.hpp"
#include "solver/fem/Modelling.hpp"
#include "solver/nonlinear/StepConstraint.hpp"

#include <array>
#include <memory>

namespace stella::contact::lac {

class LacContactConstraint : public StepConstraint {
public:
  LacContactConstraint(std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs,
                       fem::Modelling modelling);

  std::string effects() const override;
  std::vector<std::string> zoneEffects() const override;
  std::string workSummary() const override;
  void beginStep(const Eigen::VectorXd& u, double time) override;
  void addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                 std::vector<Eigen::Triplet<double>>* tangent) override;
  bool symmetric() const override { return !consistent_; }
  void correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
               SaddleSolver& solver) override;
  bool acceptConvergence(const Eigen::VectorXd& u) override;
  std::string iterationNote() const override;
  std::string continuationNote() const override { return continuation_; }
  void reportStep(std::ostream& log) const override;
  void store(ResultStep& step) const override;
  std::string singularNote() const override;

  // Per patch of Mesh::lacPatches() (for tests).
  const std::vector<double>& pressures() const { return lagsC_; }
  std::vector<double> meanGaps(const Eigen::VectorXd& u) const;
  int pairings() const { return pairings_; }

private:
  void pairAt(const Eigen::VectorXd& u);
  // ALGO_RESO_GEOM='NEWTON' in 2D: the consistent geometric tangent (LacGeometricTangent.cpp).
  // The gap row of patch p: dg_P/du = (dG_P/du - g_P dL_P/du) / L_P, every variation included.
  std::vector<std::pair<int, double>> exactGapRow(std::size_t p) const;
  // -d(forces)/du of a patch: rho c (dg_P/du)^T + (lambda_P + rho g_P) dc/du (c = dG_P with the
  // geometry held, the force's direction); zeros when `on` is false (the pattern of the pairing).
  void addGeometricTangent(std::size_t p, bool on, double pressure,
                           std::vector<Eigen::Triplet<double>>& tangent) const;
  // The coefficients of a patch's mean-gap row in the Schur complement: dg_P/du (consistent) or
  // dG_P / L_P (the geometry held).
  std::vector<std::pair<int, double>> gapRow(std::size_t p) const;
  double gapAt(std::size_t p, const Eigen::VectorXd& u) const; // mean gap, linearised on the pairing
  bool paired(std::size_t p) const { return rows_[p].pairedLength > 0.0; }
  std::vector<char> statusAt(const Eigen::VectorXd& u) const;
  const std::vector<char>& currentStatus(const Eigen::VectorXd& u);
  bool statusSettled(const Eigen::VectorXd& u);
  bool geometrySettled(const Eigen::VectorXd& u);
  double geometricResidual(const Eigen::VectorXd& u) const;
  [[noreturn]] void redundant(std::size_t patch, bool slip) const;
  struct SchurRow {
    std::size_t patch = 0;
    int direction = -1; // the mean slip along tau_direction of a sticking patch; -1: its mean gap
    bool slip() const { return direction >= 0; }
  };
  void eliminate(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                 SaddleSolver& solver, const std::vector<SchurRow>& rows);
  void applyMultipliers(const Eigen::VectorXd& y, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                        SaddleSolver& solver, const std::vector<SchurRow>& rows,
                        const std::vector<std::map<int, double>>& columns);

  // Friction (FROTTEMENT='COULOMB', 2D and 3D; LacFriction.cpp). Status per patch: 0 open, 1 contact
  // (and sticking with friction), 2 contact sliding. Tangential vectors: their components along
  // tau_1 (and tau_2 in 3D), LacPairing.hpp.
  using Tangential = std::array<double, 2>;
  bool friction() const { return definition_->hasFriction(); }
  std::size_t directions() const { return directions_; }
  Tangential slipAt(std::size_t p, const Eigen::VectorXd& u) const;    // mean slip since the step's start
  Tangential indicator(std::size_t p, const Eigen::VectorXd& u) const; // q = lambda_t + rho_t s
  double frictionLimit(std::size_t p) const;                           // mu |lambda_P|
  char contactCode(std::size_t p, const Eigen::VectorXd& u) const;
  Tangential tangentialPressure(std::size_t p, char s, const Eigen::VectorXd& u) const;
  // -mu q/|q| for a patch sliding with friction (the factors of dS_P,a in its pressure's column), else 0
  Tangential slidingCoupling(std::size_t p, const Eigen::VectorXd& u) const;
  void addFrictionForces(std::size_t p, char s, const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                         std::vector<Eigen::Triplet<double>>* tangent) const;
  // 3D sliding: the tangential multiplier as a Newton unknown (LacFriction.cpp), linearised at u.
  struct SlidingNewton {
    bool active = false;
    Tangential e{0.0, 0.0}; // the sliding direction q / |q|
    double beta = 0.0;      // mu |lambda| / (|q| - mu |lambda|)
    Tangential r{0.0, 0.0}; // lambda_t - mu |lambda| e, the equation's residual
  };
  SlidingNewton slidingNewton(std::size_t p, char s, const Eigen::VectorXd& u) const;
  // After a correction ddu at u: the tangential multipliers of the sliding patches.
  void updateSlidingPressures(const Eigen::VectorXd& u, const Eigen::VectorXd& ddu,
                              const std::vector<char>& status, const std::vector<SlidingNewton>& newton);
  bool frictionSettled();
  void storeFriction(Field& out, std::size_t c0) const;

  std::shared_ptr<const ContactDefinition> definition_;
  const DofMap& dofs_;
  fem::Modelling modelling_;
  std::vector<LacZoneCells> zones_;
  std::vector<int> patchZone_;    // per patch: zone occurrence, -1 when in no LAC zone
  std::vector<NodeId> patchNode_; // per patch: the node carrying its LAGS_C
  std::vector<int> contactEquations_;
  std::vector<LacPatchRow> rows_; // per patch, at uPairing_
  bool consistent_ = false;       // ALGO_RESO_GEOM='NEWTON' in 2D: the consistent geometric tangent
  std::vector<std::vector<std::pair<int, double>>> gapRows_; // per patch: dg_P/du when consistent_
  Eigen::VectorXd uPairing_;
  Eigen::VectorXd uStart_;
  double time_ = 0.0;
  double rho_ = 100.0;
  double rhoT_ = 100.0;                // the friction augmentation (no COEF_FROT for LAC zones)
  std::size_t directions_ = 1;         // tangent directions: 1 in 2D, 2 in 3D
  std::vector<Tangential> lagsT_;      // per patch: tangential pressure along tau_a (LacPairing.hpp)
  std::vector<Tangential> lagsTStart_; // per patch
  std::vector<double> limitBefore_;    // per patch: mu |lambda_P| before and after the last correction
  std::vector<double> limitAfter_;
  std::vector<double> lagsC_;      // per patch
  std::vector<double> lagsCStart_; // per patch
  std::vector<char> status_;       // per patch, in use
  std::vector<char> lastStatus_;   // per patch, at the last correction
  std::vector<char> accepted_;     // per patch, at the last accepted step
  std::vector<double> stepGaps_;   // per patch, mean gap at the last accepted step (NaN: not paired)
  bool useInitial_ = true;
  bool firstStep_ = true;
  bool everPaired_ = false;
  int statusIterations_ = 0;
  int geometricIterations_ = 0;
  int pairings_ = 0;
  int eliminations_ = 0;
  std::string continuation_;
  int noteActive_ = 0;
  double notePenetration_ = 0.0;
};

} // namespace stella::contact::lac
