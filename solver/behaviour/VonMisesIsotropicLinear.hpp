#pragma once
// RELATION='VMIS_ISOT_LINE': von Mises plasticity with linear isotropic hardening (ECRO_LINE:
// D_SIGM_EPSI = ET, the tangent modulus of the uniaxial curve, and SY, the yield stress).
// Hardening modulus H = E ET / (E - ET); perfectly plastic when ET = 0. Radial return and the
// consistent tangent; the prediction tangent is the continuum elastoplastic one when the point
// was plastic in the previous step. Internal variables as code_aster's VARI: V1 = cumulated
// plastic strain p, V2 = plastic indicator (1 if the step was plastic, else 0).

#include "solver/behaviour/Behaviour.hpp"

namespace stella::behaviour {

struct LinearHardening {
  double tangentModulus = 0.0; // D_SIGM_EPSI (ET)
  double yieldStress = 0.0;    // SY
};

class VonMisesIsotropicLinear final : public Behaviour {
public:
  // Throws std::invalid_argument if ET >= E, ET < 0 or SY <= 0.
  VonMisesIsotropicLinear(ElasticParameters e, LinearHardening h);
  std::string_view name() const override { return "VMIS_ISOT_LINE"; }
  int internalVariableCount() const override { return 2; }
  bool isLinear() const override { return false; }
  const ElasticParameters& elasticity() const override { return elastic_; }
  double hardeningModulus() const { return h_; }
  IntegrationStatus integrate(const PointInput& in, PointOutput& out) const override;

private:
  // Elastoplastic tangent for trial deviator direction `unitDeviator` (Mandel, unit norm),
  // theta and gammaBar as in the radial-return linearisation.
  Matrix6 tangent(const Vector6& unitDeviatorMandel, double theta, double gammaBar) const;

  ElasticParameters elastic_;
  LinearHardening hardening_;
  double h_;
  Matrix6 d_;
};

} // namespace stella::behaviour
