// Behaviour tests: uniaxial tension past yield against the closed form (with hardening and
// perfectly plastic), elastic unloading, and consistent tangents against finite differences of
// the stress update in 3D, D_PLAN, AXIS and C_PLAN.

#include "solver/behaviour/LinearElastic.hpp"
#include "solver/behaviour/VonMisesIsotropicLinear.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace stella::behaviour {
namespace {

const ElasticParameters steel{200000.0, 0.3};

struct State {
  Vector6 strain = Vector6::Zero();
  Vector6 stress = Vector6::Zero();
  std::array<double, 2> vari{0.0, 0.0};
};

// One strain-driven step in XX with sigma_yy = sigma_zz = 0 (uniaxial stress): Newton on the
// lateral strain increments with the behaviour's own tangent.
State uniaxialStep(const Behaviour& b, const State& s, double dExx) {
  Vector6 de = Vector6::Zero();
  de[0] = dExx;
  de[1] = de[2] = -0.3 * dExx;
  State next = s;
  for (int it = 0; it < 30; ++it) {
    PointInput in{s.strain, de, s.stress, s.vari, Option::Full};
    PointOutput out;
    out.internalEnd = next.vari;
    b.integrate(in, out);
    next.stress = out.stress;
    if (std::abs(out.stress[1]) + std::abs(out.stress[2]) < 1e-9) {
      break;
    }
    const Eigen::Matrix2d k = out.tangent.block<2, 2>(1, 1);
    const Eigen::Vector2d corr = k.lu().solve(out.stress.segment<2>(1));
    de.segment<2>(1) -= corr;
  }
  next.strain = s.strain + de;
  return next;
}

double closedFormStress(double eps, double e, double sy, double et) {
  const double ey = sy / e;
  return eps <= ey ? e * eps : sy + et * (eps - ey);
}

TEST(VonMisesIsotropicLinear, UniaxialTensionMatchesClosedForm) {
  for (double et : {20000.0, 0.0}) {
    const VonMisesIsotropicLinear b(steel, {et, 400.0});
    State s;
    const double ey = 400.0 / steel.youngModulus;
    for (int step = 1; step <= 10; ++step) {
      s = uniaxialStep(b, s, 0.5 * ey);
      const double eps = s.strain[0];
      const double expected = closedFormStress(eps, steel.youngModulus, 400.0, et);
      EXPECT_NEAR(s.stress[0], expected, 1e-9 * 400.0) << "ET=" << et << " step " << step;
      // uniaxial: p = plastic strain = eps - sigma / E
      EXPECT_NEAR(s.vari[0], eps - expected / steel.youngModulus, 1e-12) << "ET=" << et;
      EXPECT_EQ(s.vari[1], eps > ey * (1 + 1e-12) ? 1.0 : 0.0) << "ET=" << et << " step " << step;
    }
    // unloading by one yield strain: elastic, sigma drops by SY, p unchanged, indicator 0
    const State before = s;
    s = uniaxialStep(b, s, -ey);
    EXPECT_NEAR(s.stress[0], before.stress[0] - 400.0, 1e-9 * 400.0);
    EXPECT_DOUBLE_EQ(s.vari[0], before.vari[0]);
    EXPECT_EQ(s.vari[1], 0.0);
  }
}

TEST(VonMisesIsotropicLinear, HardeningModulusFromTangentModulus) {
  const VonMisesIsotropicLinear b(steel, {20000.0, 400.0});
  EXPECT_NEAR(b.hardeningModulus(), 200000.0 * 20000.0 / 180000.0, 1e-9);
  EXPECT_THROW(VonMisesIsotropicLinear(steel, {200000.0, 400.0}), std::invalid_argument);
}

// Finite-difference tangent of the stress update, in a modelling's layout.
void checkTangent(const Behaviour& b, fem::Modelling m, const Eigen::VectorXd& de0,
                  const Eigen::VectorXd& sigma0, std::array<double, 2> vari0) {
  const int n = fem::strainSize(m);
  Eigen::VectorXd eps0 = Eigen::VectorXd::Zero(n);
  auto run = [&](Eigen::VectorXd de, Eigen::MatrixXd* tangent) {
    Eigen::VectorXd sigma(n);
    std::array<double, 2> vari{};
    const auto status =
        integrateInModelling(b, m, Option::Full, eps0, de, sigma0, vari0, sigma, vari, tangent);
    EXPECT_EQ(status, IntegrationStatus::Ok);
    return sigma;
  };
  Eigen::MatrixXd t;
  run(de0, &t);
  const double h = 1e-8;
  Eigen::MatrixXd fd = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    if (m == fem::Modelling::PlaneStress && j == 2) {
      continue; // eps_zz is not an input in plane stress
    }
    Eigen::VectorXd p = de0, q = de0;
    p[j] += h;
    q[j] -= h;
    fd.col(j) = (run(p, nullptr) - run(q, nullptr)) / (2 * h);
  }
  EXPECT_LT((fd - t).cwiseAbs().maxCoeff(), 1e-6 * t.cwiseAbs().maxCoeff()) << fem::modellingName(m) << "\n"
                                                                            << fd << "\n\n"
                                                                            << t;
}

TEST(VonMisesIsotropicLinear, ConsistentTangentMatchesFiniteDifferences) {
  for (double et : {20000.0, 0.0}) {
    const VonMisesIsotropicLinear b(steel, {et, 400.0});
    Eigen::VectorXd de(6), s0(6);
    de << 3e-3, -1e-3, 0.5e-3, 2e-3, -1e-3, 0.7e-3;
    s0 << 100, 50, -20, 30, 10, -5;
    checkTangent(b, fem::Modelling::ThreeD, de, s0, {0.001, 1.0});
    for (fem::Modelling m :
         {fem::Modelling::PlaneStrain, fem::Modelling::Axisymmetric, fem::Modelling::PlaneStress}) {
      Eigen::VectorXd de2(4), s2(4);
      de2 << 3e-3, -1e-3, m == fem::Modelling::PlaneStrain ? 0.0 : 0.5e-3, 2e-3;
      s2 << 100, 50, m == fem::Modelling::PlaneStress ? 0.0 : -20, 30;
      if (m == fem::Modelling::PlaneStress) {
        de2[2] = 0.0;
      }
      checkTangent(b, m, de2, s2, {0.0, 0.0});
    }
  }
}

// After a plastic step, the prediction tangent (RIGI_MECA_TANG) is the continuum elastoplastic
// one: under uniaxial stress its apparent modulus 1 / (C^-1)_xx is the tangent modulus ET.
TEST(VonMisesIsotropicLinear, PredictionTangentGivesTheUniaxialTangentModulus) {
  const VonMisesIsotropicLinear b(steel, {20000.0, 400.0});
  State s;
  for (int step = 0; step < 4; ++step) {
    s = uniaxialStep(b, s, 1e-3);
  }
  ASSERT_EQ(s.vari[1], 1.0);
  PointInput in{s.strain, Vector6::Zero(), s.stress, s.vari, Option::PredictionTangent};
  PointOutput out;
  b.integrate(in, out);
  EXPECT_NEAR(1.0 / out.tangent.inverse()(0, 0), 20000.0, 1e-6 * 20000.0);
  // elastic before any plasticity
  const State fresh;
  PointInput in0{fresh.strain, Vector6::Zero(), fresh.stress, fresh.vari, Option::PredictionTangent};
  b.integrate(in0, out);
  EXPECT_NEAR(1.0 / out.tangent.inverse()(0, 0), steel.youngModulus, 1e-6 * steel.youngModulus);
}

TEST(VonMisesIsotropicLinear, PlaneStressKeepsSigmaZzZero) {
  const VonMisesIsotropicLinear b(steel, {20000.0, 400.0});
  Eigen::VectorXd eps0 = Eigen::VectorXd::Zero(4), de(4), s0 = Eigen::VectorXd::Zero(4), s(4);
  de << 5e-3, 1e-3, 0.0, 1e-3;
  std::array<double, 2> v0{0, 0}, v1{};
  Eigen::MatrixXd t;
  ASSERT_EQ(integrateInModelling(b, fem::Modelling::PlaneStress, Option::Full, eps0, de, s0, v0, s, v1, &t),
            IntegrationStatus::Ok);
  EXPECT_EQ(s[2], 0.0);
  EXPECT_GT(v1[0], 0.0);
  EXPECT_LT(de[2], 0.0); // plastic incompressibility and Poisson thin the plate
  // the von Mises stress is on the hardened yield surface
  const double vm = std::sqrt(s[0] * s[0] - s[0] * s[1] + s[1] * s[1] + 3 * s[3] * s[3]);
  EXPECT_NEAR(vm, 400.0 + b.hardeningModulus() * v1[0], 1e-7 * vm);
}

TEST(LinearElastic, StressIsDTimesStrainAndTangentIsD) {
  const LinearElastic b(steel);
  Vector6 de;
  de << 1e-3, 0, 0, 0, 0, 0;
  std::array<double, 1> v0{0}, v1{7};
  PointInput in{Vector6::Zero(), de, Vector6::Zero(), v0, Option::Full};
  PointOutput out;
  out.internalEnd = v1;
  b.integrate(in, out);
  const double l = steel.lameLambda(), mu = steel.shearModulus();
  EXPECT_NEAR(out.stress[0], (l + 2 * mu) * 1e-3, 1e-9);
  EXPECT_NEAR(out.stress[1], l * 1e-3, 1e-9);
  EXPECT_EQ(v1[0], 0.0);
  // plane stress condensed matrix: E/(1-nu^2) [1 nu; nu 1]
  const Eigen::MatrixXd cp = elasticMatrix(fem::Modelling::PlaneStress, steel);
  EXPECT_NEAR(cp(0, 0), steel.youngModulus / (1 - 0.09), 1e-6);
  EXPECT_NEAR(cp(0, 1), 0.3 * steel.youngModulus / (1 - 0.09), 1e-6);
  EXPECT_NEAR(cp(3, 3), mu, 1e-9);
}

} // namespace
} // namespace stella::behaviour
