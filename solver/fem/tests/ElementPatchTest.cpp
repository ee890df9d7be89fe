// Element verification: constant-strain patch tests on meshes of curved, distorted cells for
// every cell type and modelling, and the rigid-body null space of single element stiffnesses.

#include "solver/behaviour/Elasticity.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "solver/fem/ReferenceElement.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella::fem {
namespace {

struct Case {
  CellType type;
  Modelling modelling;
  VolumeStrain volumeStrain = VolumeStrain::Pointwise;
};

std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (CellType t :
       {CellType::TETRA4, CellType::TETRA10, CellType::PENTA6, CellType::PENTA15, CellType::PENTA18,
        CellType::PYRAM5, CellType::PYRAM13, CellType::HEXA8, CellType::HEXA20, CellType::HEXA27}) {
    cases.push_back({t, Modelling::ThreeD});
  }
  for (CellType t : {CellType::TRIA3, CellType::TRIA6, CellType::QUAD4, CellType::QUAD8, CellType::QUAD9}) {
    for (Modelling m : {Modelling::PlaneStrain, Modelling::PlaneStress, Modelling::Axisymmetric}) {
      cases.push_back({t, m});
    }
  }
  // the mean-dilatation cells of 3D_SI, D_PLAN_SI, AXIS_SI
  for (CellType t : {CellType::HEXA8, CellType::HEXA20, CellType::PENTA6, CellType::TETRA4}) {
    cases.push_back({t, Modelling::ThreeD, VolumeStrain::CellMean});
  }
  for (CellType t : {CellType::TRIA3, CellType::QUAD4, CellType::QUAD8, CellType::QUAD9}) {
    for (Modelling m : {Modelling::PlaneStrain, Modelling::Axisymmetric}) {
      cases.push_back({t, m, VolumeStrain::CellMean});
    }
  }
  return cases;
}

std::string label(const Case& c) {
  return std::string(name(c.type)) + "/" + std::string(modellingName(c.modelling)) +
         (c.volumeStrain == VolumeStrain::CellMean ? "_SI" : "");
}

// Moves interior nodes by a smooth function of position (so that quadratic cells get curved
// edges); nodes on the boundary of the unit box stay. Returns the boundary flags.
std::vector<bool> distort(PlainMesh& mesh) {
  const int dim = mesh.dimension;
  std::vector<bool> boundary(static_cast<std::size_t>(mesh.nodeCount()));
  for (int n = 0; n < mesh.nodeCount(); ++n) {
    Eigen::VectorXd x = mesh.coordinates.row(n).transpose();
    double bump = 1.0;
    bool onBoundary = false;
    for (int d = 0; d < dim; ++d) {
      bump *= 4.0 * x[d] * (1.0 - x[d]);
      onBoundary = onBoundary || std::abs(x[d]) < 1e-12 || std::abs(x[d] - 1.0) < 1e-12;
    }
    boundary[static_cast<std::size_t>(n)] = onBoundary;
    for (int d = 0; d < dim; ++d) {
      mesh.coordinates(n, d) += 0.06 * bump * std::sin(3.0 * x[(d + 1) % dim] + 1.7 * d + 0.4);
    }
  }
  return boundary;
}

Eigen::MatrixXd gradientOfExactField(Modelling m) {
  if (m == Modelling::ThreeD) {
    Eigen::MatrixXd a(3, 3);
    a << 1e-3, 2e-3, -1e-3, 0.5e-3, -2e-3, 3e-3, 1.5e-3, 0.7e-3, 2.5e-3;
    return a;
  }
  Eigen::MatrixXd a(2, 2);
  if (m == Modelling::Axisymmetric) { // u_r = a r, u_z = d z: constant stress with sigma_rz = 0
    a << 1e-3, 0.0, 0.0, -2e-3;
  } else {
    a << 1e-3, 2e-3, -0.5e-3, -2e-3;
  }
  return a;
}

TEST(ElementPatch, ConstantStrainIsReproducedExactly) {
  const behaviour::ElasticParameters mat{1.0, 0.3};
  for (const Case& c : allCases()) {
    const int dim = spaceDimension(c.modelling);
    PlainMesh mesh = boxMesh(c.type, {dim == 3 ? 2 : 3, dim == 3 ? 2 : 3, 2}, {1.0, 1.0, 1.0});
    const std::vector<bool> boundary = distort(mesh);
    if (c.modelling == Modelling::Axisymmetric) {
      mesh.coordinates.col(0).array() += 0.5; // r in [0.5, 1.5]
    }
    const Eigen::MatrixXd grad = gradientOfExactField(c.modelling);
    const Eigen::Vector3d shift(0.3e-3, -0.2e-3, 0.1e-3);
    const int n = mesh.nodeCount() * dim;
    Eigen::VectorXd uExact(n);
    for (int a = 0; a < mesh.nodeCount(); ++a) {
      Eigen::VectorXd u = grad * mesh.coordinates.row(a).transpose();
      if (c.modelling != Modelling::Axisymmetric) {
        u += shift.head(dim);
      }
      uExact.segment(a * dim, dim) = u;
    }
    const Eigen::MatrixXd d = behaviour::elasticMatrix(c.modelling, mat);
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
    ElementKinematics kin;
    Eigen::MatrixXd ke;
    const int npc = mesh.nodesPerCell();
    std::vector<ElementKinematics> kins;
    for (int e = 0; e < mesh.cellCount(); ++e) {
      Eigen::MatrixXd x(npc, dim);
      for (int a = 0; a < npc; ++a) {
        x.row(a) = mesh.coordinates.row(mesh.cell(e)[a]);
      }
      ASSERT_NO_THROW(computeKinematics(c.type, c.modelling, x, kin, c.volumeStrain)) << label(c);
      stiffness(kin, d, ke);
      for (int a = 0; a < npc; ++a) {
        for (int b = 0; b < npc; ++b) {
          k.block(mesh.cell(e)[a] * dim, mesh.cell(e)[b] * dim, dim, dim) +=
              ke.block(a * dim, b * dim, dim, dim);
        }
      }
      kins.push_back(kin);
    }
    std::vector<int> free, fixed;
    for (int a = 0; a < mesh.nodeCount(); ++a) {
      for (int i = 0; i < dim; ++i) {
        (boundary[static_cast<std::size_t>(a)] ? fixed : free).push_back(a * dim + i);
      }
    }
    ASSERT_FALSE(free.empty()) << label(c);
    Eigen::MatrixXd kff(free.size(), free.size());
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free.size()));
    for (std::size_t i = 0; i < free.size(); ++i) {
      for (std::size_t j = 0; j < free.size(); ++j) {
        kff(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = k(free[i], free[j]);
      }
      for (int f : fixed) {
        rhs[static_cast<Eigen::Index>(i)] -= k(free[i], f) * uExact[f];
      }
    }
    const Eigen::VectorXd uf = kff.ldlt().solve(rhs);
    Eigen::VectorXd u = uExact;
    for (std::size_t i = 0; i < free.size(); ++i) {
      u[free[i]] = uf[static_cast<Eigen::Index>(i)];
    }
    EXPECT_LT((u - uExact).cwiseAbs().maxCoeff(), 1e-10 * uExact.cwiseAbs().maxCoeff()) << label(c);
    // constant stress at every Gauss point
    Eigen::VectorXd epsExact = Eigen::VectorXd::Zero(strainSize(c.modelling));
    const Eigen::MatrixXd sym = 0.5 * (grad + grad.transpose());
    if (dim == 3) {
      epsExact << sym(0, 0), sym(1, 1), sym(2, 2), 2 * sym(0, 1), 2 * sym(0, 2), 2 * sym(1, 2);
    } else {
      epsExact << sym(0, 0), sym(1, 1), c.modelling == Modelling::Axisymmetric ? grad(0, 0) : 0.0,
          2 * sym(0, 1);
    }
    const Eigen::VectorXd sigmaExact = d * epsExact;
    double worst = 0.0;
    for (int e = 0; e < mesh.cellCount(); ++e) {
      Eigen::VectorXd ue(npc * dim);
      for (int a = 0; a < npc; ++a) {
        ue.segment(a * dim, dim) = u.segment(mesh.cell(e)[a] * dim, dim);
      }
      const ElementKinematics& ke2 = kins[static_cast<std::size_t>(e)];
      for (int q = 0; q < ke2.pointCount(); ++q) {
        worst = std::max(worst, (d * strainAt(ke2, q, ue) - sigmaExact).cwiseAbs().maxCoeff());
      }
    }
    EXPECT_LT(worst, 1e-10 * sigmaExact.cwiseAbs().maxCoeff()) << label(c);
  }
}

// One distorted element: K symmetric, positive semi-definite, null space = rigid-body motions.
TEST(ElementStiffness, NullSpaceIsRigidBodyMotions) {
  const behaviour::ElasticParameters mat{1.0, 0.3};
  for (const Case& c : allCases()) {
    const ReferenceElement& ref = referenceElement(c.type);
    const int dim = spaceDimension(c.modelling);
    Eigen::MatrixXd x(ref.nodeCount(), dim);
    for (int a = 0; a < ref.nodeCount(); ++a) {
      for (int i = 0; i < dim; ++i) {
        x(a, i) = ref.node(a)[i] + 0.04 * std::sin(1.0 + 2.3 * a + 1.1 * i);
      }
      x(a, 0) += 0.5 * x(a, 1);
    }
    if (c.modelling == Modelling::Axisymmetric) {
      x.col(0).array() += 3.0;
    }
    ElementKinematics kin;
    computeKinematics(c.type, c.modelling, x, kin, c.volumeStrain);
    Eigen::MatrixXd k;
    stiffness(kin, behaviour::elasticMatrix(c.modelling, mat), k);
    EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-14 * k.cwiseAbs().maxCoeff()) << label(c);
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k).eigenvalues();
    const double tol = 1e-10 * ev.maxCoeff();
    int zero = 0;
    for (Eigen::Index i = 0; i < ev.size(); ++i) {
      EXPECT_GT(ev[i], -tol) << label(c);
      zero += std::abs(ev[i]) < tol ? 1 : 0;
    }
    int expected = dim == 3 ? 6 : 3;
    if (c.modelling == Modelling::Axisymmetric) {
      // one rigid motion (axial translation); a one-point TRIA3 leaves 4 strains for 5 DOFs
      expected = c.type == CellType::TRIA3 ? 2 : 1;
    }
    EXPECT_EQ(zero, expected) << label(c);
  }
}

} // namespace
} // namespace stella::fem
