#pragma once
// Constitutive behaviours (COMPORTEMENT RELATION=...), integrated at one Gauss point over a step
// as code_aster does: from the strain at the start, the strain increment, the stress and
// internal variables at the start, compute the stress and internal variables at the end and,
// on request, the tangent.
//
// Behaviours work on 3D vectors (XX, YY, ZZ, XY, XZ, YZ; engineering shear strains, tensor
// shear stresses). integrateInModelling() adapts them to D_PLAN / AXIS (4 components) and
// C_PLAN (local iterations on the out-of-plane strain so that sigma_zz = 0).

#include "solver/behaviour/Elasticity.hpp"

#include <span>
#include <string_view>

namespace stella::behaviour {

// What the driver asks (code_aster's options): the tangent at the start of the step without
// integrating (prediction, RIGI_MECA_TANG), integration and tangent (FULL_MECA), integration
// only (RAPH_MECA), or the elastic matrix (RIGI_MECA_ELAS, MATRICE='ELASTIQUE').
enum class Option { PredictionTangent, Full, ResidualOnly, ElasticTangent };

inline bool needsTangent(Option o) {
  return o != Option::ResidualOnly;
}
inline bool integrates(Option o) {
  return o == Option::Full || o == Option::ResidualOnly;
}

enum class IntegrationStatus { Ok, Failed }; // Failed: local non-convergence (step cut event)

struct PointInput {
  Vector6 strainStart = Vector6::Zero();
  Vector6 strainIncrement = Vector6::Zero();
  Vector6 stressStart = Vector6::Zero();
  std::span<const double> internalStart;
  Option option = Option::Full;
};

struct PointOutput {
  Vector6 stress = Vector6::Zero();
  std::span<double> internalEnd; // internalVariableCount() values
  Matrix6 tangent = Matrix6::Zero();
};

class Behaviour {
public:
  virtual ~Behaviour() = default;
  virtual std::string_view name() const = 0; // code_aster's RELATION
  virtual int internalVariableCount() const = 0;
  virtual bool isLinear() const = 0; // no return mapping, one Newton iteration suffices
  virtual bool symmetricTangent() const { return true; }
  virtual const ElasticParameters& elasticity() const = 0;
  virtual IntegrationStatus integrate(const PointInput& in, PointOutput& out) const = 0;
};

// Integration in a modelling's layout (strainSize components). In C_PLAN the ZZ component of
// `strainIncrement` is an output (the out-of-plane strain increment found by local Newton
// iterations); `tangent` (may be null) receives the reduced/condensed tangent.
IntegrationStatus integrateInModelling(const Behaviour& b, fem::Modelling m, Option option,
                                       const Eigen::Ref<const Eigen::VectorXd>& strainStart,
                                       Eigen::Ref<Eigen::VectorXd> strainIncrement,
                                       const Eigen::Ref<const Eigen::VectorXd>& stressStart,
                                       std::span<const double> internalStart,
                                       Eigen::Ref<Eigen::VectorXd> stress, std::span<double> internalEnd,
                                       Eigen::MatrixXd* tangent);

} // namespace stella::behaviour
