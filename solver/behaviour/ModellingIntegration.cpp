// Behaviour integration in the layouts of D_PLAN, AXIS (eps_xz = eps_yz = 0) and C_PLAN
// (Newton iterations on eps_zz until sigma_zz = 0, then static condensation of the tangent).

#include "solver/behaviour/Behaviour.hpp"

#include <cmath>

namespace stella::behaviour {
namespace {

Vector6 expand(const Eigen::Ref<const Eigen::VectorXd>& v) {
  Vector6 r = Vector6::Zero();
  r.head(4) = v.head(4);
  return r;
}

} // namespace

IntegrationStatus integrateInModelling(const Behaviour& b, fem::Modelling m, Option option,
                                       const Eigen::Ref<const Eigen::VectorXd>& strainStart,
                                       Eigen::Ref<Eigen::VectorXd> strainIncrement,
                                       const Eigen::Ref<const Eigen::VectorXd>& stressStart,
                                       std::span<const double> internalStart,
                                       Eigen::Ref<Eigen::VectorXd> stress, std::span<double> internalEnd,
                                       Eigen::MatrixXd* tangent) {
  PointInput in;
  PointOutput out;
  in.option = option;
  in.internalStart = internalStart;
  out.internalEnd = internalEnd;
  if (m == fem::Modelling::ThreeD) {
    in.strainStart = strainStart;
    in.strainIncrement = strainIncrement;
    in.stressStart = stressStart;
    const IntegrationStatus s = b.integrate(in, out);
    if (integrates(option)) {
      stress = out.stress;
    }
    if (tangent != nullptr && needsTangent(option)) {
      *tangent = out.tangent;
    }
    return s;
  }
  in.strainStart = expand(strainStart);
  in.stressStart = expand(stressStart);
  in.strainIncrement = expand(strainIncrement);
  if (m == fem::Modelling::PlaneStress && integrates(option)) {
    const ElasticParameters& e = b.elasticity();
    const double nu = e.poissonRatio;
    // elastic guess, then Newton on deps_zz with the consistent tangent's ZZ-ZZ term
    in.strainIncrement[2] = -(nu / (1.0 - nu)) * (in.strainIncrement[0] + in.strainIncrement[1]) -
                            in.stressStart[2] * (1.0 - nu * nu) / (e.youngModulus * (1.0 - nu));
    const double scale = std::max(in.stressStart.norm(), 1e-300) + e.youngModulus * in.strainIncrement.norm();
    PointInput probe = in;
    probe.option = Option::Full;
    bool converged = false;
    for (int it = 0; it < 50; ++it) {
      if (b.integrate(probe, out) != IntegrationStatus::Ok) {
        return IntegrationStatus::Failed;
      }
      if (std::abs(out.stress[2]) <= 1e-12 * scale) {
        converged = true;
        break;
      }
      probe.strainIncrement[2] -= out.stress[2] / out.tangent(2, 2);
    }
    if (!converged) {
      return IntegrationStatus::Failed;
    }
    strainIncrement[2] = probe.strainIncrement[2];
    stress = out.stress.head(4);
    stress[2] = 0.0;
    if (tangent != nullptr && needsTangent(option)) {
      *tangent = reduceTangent(m, out.tangent);
    }
    return IntegrationStatus::Ok;
  }
  const IntegrationStatus s = b.integrate(in, out);
  if (integrates(option)) {
    stress = out.stress.head(4);
  }
  if (tangent != nullptr && needsTangent(option)) {
    *tangent = reduceTangent(m, out.tangent);
  }
  return s;
}

} // namespace stella::behaviour
