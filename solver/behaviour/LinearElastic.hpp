#pragma once
// RELATION='ELAS': isotropic linear elasticity; no return mapping. One internal variable,
// always 0 (code_aster's VARI of ELAS has one component).

#include "solver/behaviour/Behaviour.hpp"

namespace stella::behaviour {

class LinearElastic final : public Behaviour {
public:
  explicit LinearElastic(ElasticParameters p);
  std::string_view name() const override { return "ELAS"; }
  int internalVariableCount() const override { return 1; }
  bool isLinear() const override { return true; }
  const ElasticParameters& elasticity() const override { return params_; }
  IntegrationStatus integrate(const PointInput& in, PointOutput& out) const override;

private:
  ElasticParameters params_;
  Matrix6 d_;
};

} // namespace stella::behaviour
