// ELAS: sigma = sigma_start + D deps.

#include "solver/behaviour/LinearElastic.hpp"

namespace stella::behaviour {

LinearElastic::LinearElastic(ElasticParameters p) : params_(p), d_(isotropicStiffness(p)) {}

IntegrationStatus LinearElastic::integrate(const PointInput& in, PointOutput& out) const {
  if (integrates(in.option)) {
    out.stress = in.stressStart + d_ * in.strainIncrement;
    if (!out.internalEnd.empty()) {
      out.internalEnd[0] = 0.0;
    }
  }
  if (needsTangent(in.option)) {
    out.tangent = d_;
  }
  return IntegrationStatus::Ok;
}

} // namespace stella::behaviour
