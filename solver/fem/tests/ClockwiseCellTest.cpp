// 2D cells numbered clockwise (Salome and older meshers write them so) are accepted in D_PLAN,
// C_PLAN and AXIS as in code_aster: the weights use |det J|, so a cell and its reversal (the same
// nodes in the opposite order) give the same stiffness, volume forces and strains, and a mesh
// whose cells are all or partly reversed gives the same global stiffness and the same solution
// (a patch test) to round-off. A 3D inverted cell stays an error, and so does a folded 2D cell.

#include "solver/behaviour/Elasticity.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "solver/fem/Kinematics.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/loads/SkinLoads.hpp"
#include "solver/mesh/MeshTransform.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella::fem {
namespace {

struct Case {
  CellType type;
  Modelling modelling;
  VolumeStrain volumeStrain = VolumeStrain::Pointwise;
};

std::vector<Case> planeCases() {
  std::vector<Case> cases;
  for (CellType t : {CellType::TRIA3, CellType::TRIA6, CellType::QUAD4, CellType::QUAD8, CellType::QUAD9}) {
    for (Modelling m : {Modelling::PlaneStrain, Modelling::PlaneStress, Modelling::Axisymmetric}) {
      cases.push_back({t, m});
    }
  }
  for (CellType t : {CellType::TRIA3, CellType::QUAD4, CellType::QUAD8, CellType::QUAD9}) {
    for (Modelling m : {Modelling::PlaneStrain, Modelling::Axisymmetric}) {
      cases.push_back({t, m, VolumeStrain::CellMean}); // D_PLAN_SI, AXIS_SI
    }
  }
  return cases;
}

std::string label(const Case& c) {
  return std::string(name(c.type)) + "/" + std::string(modellingName(c.modelling)) +
         (c.volumeStrain == VolumeStrain::CellMean ? "_SI" : "");
}

// Element stiffness with K(a, b) blocks for nodes a, b.
Eigen::MatrixXd elementStiffness(const Case& c, const Eigen::MatrixXd& x) {
  ElementKinematics kin;
  computeKinematics(c.type, c.modelling, x, kin, c.volumeStrain);
  Eigen::MatrixXd k;
  stiffness(kin, behaviour::elasticMatrix(c.modelling, {1.0, 0.3}), k);
  return k;
}

// K of the reversed cell, its nodes put back in the original order.
Eigen::MatrixXd unpermuted(const Eigen::MatrixXd& kr, const std::vector<int>& perm, int dim) {
  Eigen::MatrixXd k(kr.rows(), kr.cols());
  const auto n = static_cast<int>(perm.size());
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      k.block(perm[static_cast<std::size_t>(a)] * dim, perm[static_cast<std::size_t>(b)] * dim, dim, dim) =
          kr.block(a * dim, b * dim, dim, dim);
    }
  }
  return k;
}

TEST(ClockwiseCell, ReversedCellHasTheSameStiffnessAndLoads) {
  for (const Case& c : planeCases()) {
    const ReferenceElement& ref = referenceElement(c.type);
    Eigen::MatrixXd x(ref.nodeCount(), 2);
    for (int a = 0; a < ref.nodeCount(); ++a) {
      for (int i = 0; i < 2; ++i) {
        x(a, i) = ref.node(a)[i] + 0.04 * std::sin(1.0 + 2.3 * a + 1.1 * i);
      }
      x(a, 0) += 0.5 * x(a, 1) + 3.0;
    }
    const auto perm = orientationReversal(c.type);
    Eigen::MatrixXd xr(x.rows(), 2);
    for (std::size_t a = 0; a < perm.size(); ++a) {
      xr.row(static_cast<Eigen::Index>(a)) = x.row(perm[a]);
    }
    const Eigen::MatrixXd k = elementStiffness(c, x);
    Eigen::MatrixXd kr;
    ASSERT_NO_THROW(kr = elementStiffness(c, xr)) << label(c);
    EXPECT_LT((unpermuted(kr, perm, 2) - k).cwiseAbs().maxCoeff(), 1e-13 * k.cwiseAbs().maxCoeff())
        << label(c);
    // Weights sum to the area (times 2 pi r in AXIS, without the 2 pi) either way: positive.
    ElementKinematics kin;
    computeKinematics(c.type, c.modelling, xr, kin, c.volumeStrain);
    for (double w : kin.weights) {
      EXPECT_GT(w, 0.0) << label(c);
    }
    const Eigen::Vector2d g(0.3, -1.0);
    const Eigen::VectorXd f = loads::volumeForces(c.type, c.modelling, x, g);
    const Eigen::VectorXd fr = loads::volumeForces(c.type, c.modelling, xr, g);
    for (std::size_t a = 0; a < perm.size(); ++a) {
      EXPECT_LT((fr.segment(static_cast<Eigen::Index>(a) * 2, 2) - f.segment(perm[a] * 2, 2)).norm(),
                1e-13 * f.norm())
          << label(c);
    }
  }
}

TEST(ClockwiseCell, FoldedPlaneCellAndInverted3DCellAreErrors) {
  // A bow-tie QUAD4: det J changes sign inside the cell.
  Eigen::MatrixXd folded(4, 2);
  folded << 0, 0, 1, 0, 0, 1, 1, 1;
  ElementKinematics kin;
  EXPECT_THROW(computeKinematics(CellType::QUAD4, Modelling::PlaneStrain, folded, kin),
               DegenerateElementError);
  // A reversed HEXA8 (every det J < 0).
  const ReferenceElement& ref = referenceElement(CellType::HEXA8);
  const auto perm = orientationReversal(CellType::HEXA8);
  Eigen::MatrixXd x(8, 3);
  for (int a = 0; a < 8; ++a) {
    for (int i = 0; i < 3; ++i) {
      x(a, i) = ref.node(perm[static_cast<std::size_t>(a)])[i];
    }
  }
  EXPECT_THROW(computeKinematics(CellType::HEXA8, Modelling::ThreeD, x, kin), DegenerateElementError);
}

// Global stiffness of a box mesh (interior nodes moved so quadratic cells are curved).
Eigen::MatrixXd globalStiffness(const Case& c, const PlainMesh& mesh) {
  const int dim = 2;
  const int n = mesh.nodeCount() * dim;
  const int npc = mesh.nodesPerCell();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e < mesh.cellCount(); ++e) {
    Eigen::MatrixXd x(npc, dim);
    for (int a = 0; a < npc; ++a) {
      x.row(a) = mesh.coordinates.row(mesh.cell(e)[a]);
    }
    const Eigen::MatrixXd ke = elementStiffness(c, x);
    for (int a = 0; a < npc; ++a) {
      for (int b = 0; b < npc; ++b) {
        k.block(mesh.cell(e)[a] * dim, mesh.cell(e)[b] * dim, dim, dim) +=
            ke.block(a * dim, b * dim, dim, dim);
      }
    }
  }
  return k;
}

// Reverses the cells e with e % step == 0 (step 1: every cell).
PlainMesh reversed(PlainMesh mesh, int step) {
  const auto perm = orientationReversal(mesh.cellType);
  const int npc = mesh.nodesPerCell();
  for (int e = 0; e < mesh.cellCount(); e += step) {
    const std::vector<int> old(mesh.cell(e), mesh.cell(e) + npc);
    for (int a = 0; a < npc; ++a) {
      mesh.connectivity[static_cast<std::size_t>(e * npc + a)] =
          old[static_cast<std::size_t>(perm[static_cast<std::size_t>(a)])];
    }
  }
  return mesh;
}

// Displacement with the boundary nodes held at the linear field u = A x + s (AXIS: u_r = a r,
// u_z = d z) and a volume force, solved on the free nodes.
Eigen::VectorXd solve(const Case& c, const PlainMesh& mesh, const Eigen::MatrixXd& grad,
                      const std::vector<bool>& boundary, double gravity) {
  const int dim = 2;
  const Eigen::MatrixXd k = globalStiffness(c, mesh);
  const int n = mesh.nodeCount() * dim;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  const int npc = mesh.nodesPerCell();
  for (int e = 0; e < mesh.cellCount(); ++e) {
    Eigen::MatrixXd x(npc, dim);
    for (int a = 0; a < npc; ++a) {
      x.row(a) = mesh.coordinates.row(mesh.cell(e)[a]);
    }
    const Eigen::VectorXd fe = loads::volumeForces(c.type, c.modelling, x, Eigen::Vector2d(0.0, -gravity));
    for (int a = 0; a < npc; ++a) {
      f.segment(mesh.cell(e)[a] * dim, dim) += fe.segment(a * dim, dim);
    }
  }
  std::vector<int> free, fixed;
  for (int a = 0; a < mesh.nodeCount(); ++a) {
    u.segment(a * dim, dim) = grad * mesh.coordinates.row(a).transpose();
    for (int i = 0; i < dim; ++i) {
      (boundary[static_cast<std::size_t>(a)] ? fixed : free).push_back(a * dim + i);
    }
  }
  const auto nf = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd kff(nf, nf);
  Eigen::VectorXd rhs(nf);
  for (Eigen::Index i = 0; i < nf; ++i) {
    rhs[i] = f[free[static_cast<std::size_t>(i)]];
    for (Eigen::Index j = 0; j < nf; ++j) {
      kff(i, j) = k(free[static_cast<std::size_t>(i)], free[static_cast<std::size_t>(j)]);
    }
    for (int b : fixed) {
      rhs[i] -= k(free[static_cast<std::size_t>(i)], b) * u[b];
    }
  }
  const Eigen::VectorXd uf = kff.ldlt().solve(rhs);
  for (Eigen::Index i = 0; i < nf; ++i) {
    u[free[static_cast<std::size_t>(i)]] = uf[i];
  }
  return u;
}

TEST(ClockwiseCell, ReversedMeshesGiveTheSameSolution) {
  for (const Case& c : planeCases()) {
    PlainMesh mesh = boxMesh(c.type, {3, 3, 1}, {1.0, 1.0, 1.0});
    std::vector<bool> boundary(static_cast<std::size_t>(mesh.nodeCount()));
    for (int a = 0; a < mesh.nodeCount(); ++a) {
      const double x = mesh.coordinates(a, 0);
      const double y = mesh.coordinates(a, 1);
      const double bump = 16.0 * x * (1 - x) * y * (1 - y);
      boundary[static_cast<std::size_t>(a)] = bump < 1e-12;
      mesh.coordinates(a, 0) += 0.06 * bump * std::sin(3.0 * y + 0.4);
      mesh.coordinates(a, 1) += 0.06 * bump * std::sin(3.0 * x + 2.1);
    }
    if (c.modelling == Modelling::Axisymmetric) {
      mesh.coordinates.col(0).array() += 0.5; // r in [0.5, 1.5]
    }
    Eigen::MatrixXd grad(2, 2);
    if (c.modelling == Modelling::Axisymmetric) {
      grad << 1e-3, 0.0, 0.0, -2e-3;
    } else {
      grad << 1e-3, 2e-3, -0.5e-3, -2e-3;
    }
    const Eigen::MatrixXd k = globalStiffness(c, mesh);
    const Eigen::VectorXd patch = solve(c, mesh, grad, boundary, 0.0);
    const Eigen::VectorXd loaded = solve(c, mesh, grad, boundary, 1e-3);
    for (int step : {1, 2}) {
      const PlainMesh turned = reversed(mesh, step);
      const std::string what = label(c) + (step == 1 ? " all cells reversed" : " every other cell reversed");
      Eigen::MatrixXd kt;
      ASSERT_NO_THROW(kt = globalStiffness(c, turned)) << what;
      EXPECT_LT((kt - k).cwiseAbs().maxCoeff(), 1e-13 * k.cwiseAbs().maxCoeff()) << what;
      // Patch test: the linear field is reproduced exactly on the reversed mesh.
      Eigen::VectorXd exact(patch.size());
      for (int a = 0; a < mesh.nodeCount(); ++a) {
        exact.segment(a * 2, 2) = grad * mesh.coordinates.row(a).transpose();
      }
      const Eigen::VectorXd pt = solve(c, turned, grad, boundary, 0.0);
      EXPECT_LT((pt - exact).cwiseAbs().maxCoeff(), 1e-10 * exact.cwiseAbs().maxCoeff()) << what;
      // Under gravity (not a patch field): the same displacements as the counter-clockwise mesh.
      const Eigen::VectorXd lt = solve(c, turned, grad, boundary, 1e-3);
      EXPECT_LT((lt - loaded).cwiseAbs().maxCoeff(), 1e-10 * loaded.cwiseAbs().maxCoeff()) << what;
      EXPECT_GT((loaded - exact).cwiseAbs().maxCoeff(), 1e-3 * exact.cwiseAbs().maxCoeff()) << what;
    }
  }
}

} // namespace
} // namespace stella::fem
