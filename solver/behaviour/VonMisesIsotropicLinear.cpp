// Radial return for von Mises plasticity with linear isotropic hardening. Computations on the
// deviator are done in Mandel notation (shear components times sqrt 2) and converted to the
// engineering/tensor Voigt layout at the end.

#include "solver/behaviour/VonMisesIsotropicLinear.hpp"

#include <cmath>
#include <stdexcept>

namespace stella::behaviour {
namespace {

const double sqrt2 = std::sqrt(2.0);

// Voigt stress (tensor shears) -> Mandel deviator.
Vector6 mandelDeviator(const Vector6& s) {
  const double mean = (s[0] + s[1] + s[2]) / 3.0;
  Vector6 d;
  d << s[0] - mean, s[1] - mean, s[2] - mean, sqrt2 * s[3], sqrt2 * s[4], sqrt2 * s[5];
  return d;
}

} // namespace

VonMisesIsotropicLinear::VonMisesIsotropicLinear(ElasticParameters e, LinearHardening h)
    : elastic_(e), hardening_(h), d_(isotropicStiffness(e)) {
  if (!(h.tangentModulus >= 0.0) || !(h.tangentModulus < e.youngModulus)) {
    throw std::invalid_argument("ECRO_LINE: D_SIGM_EPSI must be in [0, E)");
  }
  if (!(h.yieldStress > 0.0)) {
    throw std::invalid_argument("ECRO_LINE: SY must be positive");
  }
  h_ = e.youngModulus * h.tangentModulus / (e.youngModulus - h.tangentModulus);
}

Matrix6 VonMisesIsotropicLinear::tangent(const Vector6& n, double theta, double gammaBar) const {
  const double mu = elastic_.shearModulus();
  const double k = elastic_.bulkModulus();
  Matrix6 c = Matrix6::Zero(); // Mandel
  for (int i = 0; i < 6; ++i) {
    c(i, i) = 2.0 * mu * theta;
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      c(i, j) += k - 2.0 * mu * theta / 3.0;
    }
  }
  c -= 2.0 * mu * gammaBar * (n * n.transpose());
  Vector6 s;
  s << 1, 1, 1, 1 / sqrt2, 1 / sqrt2, 1 / sqrt2;
  return s.asDiagonal() * c * s.asDiagonal();
}

IntegrationStatus VonMisesIsotropicLinear::integrate(const PointInput& in, PointOutput& out) const {
  const double mu = elastic_.shearModulus();
  const double pStart = in.internalStart.empty() ? 0.0 : in.internalStart[0];
  const bool wasPlastic = in.internalStart.size() > 1 && in.internalStart[1] > 0.5;
  if (in.option == Option::ElasticTangent) {
    out.tangent = d_;
    return IntegrationStatus::Ok;
  }
  if (in.option == Option::PredictionTangent) {
    const Vector6 dev = mandelDeviator(in.stressStart);
    const double norm = dev.norm();
    if (wasPlastic && norm > 0.0) {
      out.tangent = tangent(dev / norm, 1.0, 3.0 * mu / (3.0 * mu + h_));
    } else {
      out.tangent = d_;
    }
    return IntegrationStatus::Ok;
  }
  const Vector6 trial = in.stressStart + d_ * in.strainIncrement;
  const Vector6 dev = mandelDeviator(trial);
  const double qTrial = std::sqrt(1.5) * dev.norm(); // von Mises equivalent stress
  const double yield = hardening_.yieldStress + h_ * pStart;
  const double f = qTrial - yield;
  if (f <= 1e-12 * hardening_.yieldStress) {
    out.stress = trial;
    if (out.internalEnd.size() >= 2) {
      out.internalEnd[0] = pStart;
      out.internalEnd[1] = 0.0;
    }
    if (needsTangent(in.option)) {
      out.tangent = d_;
    }
    return IntegrationStatus::Ok;
  }
  const double dp = f / (3.0 * mu + h_);
  const double ratio = 3.0 * mu * dp / qTrial; // 1 - theta
  Vector6 sigma = trial;
  const double mean = (trial[0] + trial[1] + trial[2]) / 3.0;
  for (int i = 0; i < 3; ++i) {
    sigma[i] = mean + (trial[i] - mean) * (1.0 - ratio);
  }
  for (int i = 3; i < 6; ++i) {
    sigma[i] = trial[i] * (1.0 - ratio);
  }
  out.stress = sigma;
  if (out.internalEnd.size() >= 2) {
    out.internalEnd[0] = pStart + dp;
    out.internalEnd[1] = 1.0;
  }
  if (needsTangent(in.option)) {
    const double gammaBar = 3.0 * mu / (3.0 * mu + h_) - ratio;
    out.tangent = tangent(dev / dev.norm(), 1.0 - ratio, gammaBar);
  }
  return IntegrationStatus::Ok;
}

} // namespace stella::behaviour
