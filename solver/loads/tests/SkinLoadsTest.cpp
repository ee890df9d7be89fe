// Pressure and force integrals on skins and volumes against hand calculations.

#include "solver/loads/SkinLoads.hpp"

#include <gtest/gtest.h>

namespace stella::loads {
namespace {

using fem::Modelling;

// Uniform pressure p on the disc face z = 0, r in [0, R], modelled in AXIS by the edge from
// (0, 0) to (R, 0), the body above it: per radian the axial force is p R^2 / 2 (no 2 pi), and on
// one SEG2 the nodal forces are p R^2 / 6 (axis) and p R^2 / 3 (rim), pushing into the body (+Y).
TEST(SkinLoads, UniformPressureOnAxisymmetricDiscPerRadian) {
  const double p = 7.0, r = 2.0;
  Eigen::MatrixXd x(2, 2);
  x << 0.0, 0.0, r, 0.0;
  const Eigen::VectorXd f = pressureForces(CellType::SEG2, Modelling::Axisymmetric, x, Eigen::Vector2d(p, p));
  EXPECT_NEAR(f[0], 0.0, 1e-14);
  EXPECT_NEAR(f[1], p * r * r / 6.0, 1e-13);
  EXPECT_NEAR(f[2], 0.0, 1e-14);
  EXPECT_NEAR(f[3], p * r * r / 3.0, 1e-13);
  // the same disc cut in 5 SEG3 edges: the resultant is still p R^2 / 2
  double total = 0.0;
  for (int e = 0; e < 5; ++e) {
    Eigen::MatrixXd xe(3, 2);
    xe << r * e / 5.0, 0.0, r * (e + 1) / 5.0, 0.0, r * (e + 0.5) / 5.0, 0.0;
    const Eigen::VectorXd fe =
        pressureForces(CellType::SEG3, Modelling::Axisymmetric, xe, Eigen::Vector3d(p, p, p));
    total += fe[1] + fe[3] + fe[5];
  }
  EXPECT_NEAR(total, p * r * r / 2.0, 1e-12);
}

TEST(SkinLoads, PressureOnPlaneEdgeAndFaceFollowsTheNormal) {
  // edge from (1, 0) to (1, 2) in D_PLAN: tangent +Y, normal +X; force -p * L along X
  Eigen::MatrixXd x(3, 2);
  x << 1.0, 0.0, 1.0, 2.0, 1.0, 1.0;
  const Eigen::VectorXd f =
      pressureForces(CellType::SEG3, Modelling::PlaneStrain, x, Eigen::Vector3d(3, 3, 3));
  EXPECT_NEAR(f[0] + f[2] + f[4], -6.0, 1e-13);
  EXPECT_NEAR(f[1] + f[3] + f[5], 0.0, 1e-13);
  EXPECT_NEAR(f[4], -4.0, 1e-13); // SEG3 splits 1/6, 1/6, 2/3
  // QUAD8 face 2 x 3 in the plane z = 5, counter-clockwise seen from +Z: normal +Z
  Eigen::MatrixXd q(8, 3);
  q << 0, 0, 5, 2, 0, 5, 2, 3, 5, 0, 3, 5, 1, 0, 5, 2, 1.5, 5, 1, 3, 5, 0, 1.5, 5;
  const Eigen::VectorXd fq =
      pressureForces(CellType::QUAD8, Modelling::ThreeD, q, Eigen::VectorXd::Constant(8, 2.0));
  double fz = 0.0;
  for (int i = 0; i < 8; ++i) {
    fz += fq[3 * i + 2];
    EXPECT_NEAR(fq[3 * i], 0.0, 1e-13);
  }
  EXPECT_NEAR(fz, -12.0, 1e-12);
  // serendipity: corner nodes get -1/12 of the load, mid-edge nodes 1/3
  EXPECT_NEAR(fq[2], 12.0 / 12.0, 1e-12);
  EXPECT_NEAR(fq[14], -12.0 / 3.0, 1e-12);
}

TEST(SkinLoads, SurfaceAndVolumeForces) {
  Eigen::MatrixXd t(3, 3);
  t << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  const Eigen::VectorXd ft = surfaceForces(CellType::TRIA3, Modelling::ThreeD, t, Eigen::Vector3d(0, 0, 6));
  EXPECT_NEAR(ft[2] + ft[5] + ft[8], 3.0, 1e-13);
  // gravity rho g on a 2 x 1 QUAD4 in AXIS at r in [1, 3]: per radian volume = int r dr dz = 4
  Eigen::MatrixXd x(4, 2);
  x << 1, 0, 3, 0, 3, 1, 1, 1;
  const Eigen::VectorXd fv =
      volumeForces(CellType::QUAD4, Modelling::Axisymmetric, x, Eigen::Vector2d(0, -10));
  EXPECT_NEAR(fv[1] + fv[3] + fv[5] + fv[7], -40.0, 1e-12);
}

} // namespace
} // namespace stella::loads
