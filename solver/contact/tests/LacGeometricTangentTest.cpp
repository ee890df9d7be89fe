// The consistent geometric tangent of LAC contact with ALGO_RESO_GEOM='NEWTON' in 2D
// (contact/lac/LacGeometricTangent.cpp): on two blocks whose slave side is cut by DECOUPE_LAC
// (QUAD4: SEG2 patches; QUAD8: SEG3 patches, kept), moved so that the interface is tilted,
// curved, partly covered and open or penetrated patch by patch, the tangent -d(forces)/du of the
// contact forces and the mean-gap rows dg_P/du against central differences of the forces and of
// the mean gaps, each evaluated with the pairing redone at the perturbed positions (the residual
// Newton solves), for D_PLAN and AXIS, both TYPE_JACOBIEN, and LISSAGE='OUI'.

#include "solver/contact/lac/LacContactConstraint.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"
#include "solver/mesh/LacCutting.hpp"
#include "solver/model/Model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>

namespace stella::contact::lac {
namespace {

struct Case {
  CellType cell = CellType::QUAD4;
  fem::Modelling modelling = fem::Modelling::PlaneStrain;
  bool currentJacobian = false;
  bool smoothing = false; // LISSAGE='OUI'
};

struct Blocks {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<LacContactConstraint> constraint;

  explicit Blocks(const Case& c) {
    // B (3 cells) above A (4 cells) with a gap of 0.002; B's bottom is the slave
    const Mesh blocks = testing::twoBlocks(c.cell, 4, 3, 0.002);
    mesh = std::make_shared<Mesh>(cutMeshForLac(blocks, {"B_YMIN"}, LacHexaCut::Pyramids, {}));
    model = std::make_shared<Model>(mesh);
    model->components = 2;
    model->modelling = c.modelling;
    model->activeNodes.assign(static_cast<std::size_t>(mesh->nodeCount()), true);
    dofs = std::make_unique<DofMap>(*model);
    auto definition = std::make_shared<ContactDefinition>();
    definition->mesh = mesh;
    definition->settings.formulation = Formulation::Continue;
    definition->settings.continuous.geometryNewton = true;
    definition->settings.smoothing = c.smoothing;
    ContactZone zone;
    zone.masterGroup = "A_YMAX";
    zone.slaveGroup = "B_YMIN";
    zone.algorithm = ContactAlgorithm::Lac;
    zone.continuous.init = ContactInit::Yes; // every paired patch in contact: the status is fixed
    zone.continuous.lacCurrentJacobian = c.currentJacobian;
    definition->zones.push_back(zone);
    constraint = std::make_unique<LacContactConstraint>(definition, *dofs, c.modelling);
  }

  // A displacement that tilts and bends the slave block and shifts it sideways (the master's edges
  // then end inside the slave patches), bends the master, and leaves some patches open and some
  // penetrated: every variation of the mortar integrals is exercised.
  Eigen::VectorXd displacement() const {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs->physicalCount());
    for (NodeId n = 0; n < mesh->nodeCount(); ++n) {
      const Point3 x = mesh->point(n);
      const bool slave = x[1] > 1.0 + 1e-9;
      const double dx = slave ? 0.13 + 0.02 * x[1] : 0.01 * std::sin(2.0 * x[1]);
      const double dy = slave ? -0.0025 + 0.01 * x[0] - 0.012 * x[0] * x[0] : 0.001 * std::sin(3.0 * x[0]);
      for (const auto& [k, d] : {std::pair{0, dx}, std::pair{1, dy}}) {
        const int e = dofs->dof(n, k);
        if (e >= 0) {
          u(e) = d;
        }
      }
    }
    return u;
  }

  Eigen::VectorXd forces(const Eigen::VectorXd& u, std::vector<Eigen::Triplet<double>>* tangent) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(u.size());
    constraint->addForces(u, f, tangent);
    return f;
  }
};

void checkAgainstCentralDifferences(const Case& c) {
  Blocks b(c);
  const Eigen::VectorXd u = b.displacement();
  b.constraint->beginStep(u, 1.0);
  std::vector<Eigen::Triplet<double>> triplets;
  const Eigen::VectorXd f0 = b.forces(u, &triplets);
  Eigen::SparseMatrix<double> k(u.size(), u.size());
  k.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixXd tangent(k);
  const std::vector<double> g0 = b.constraint->meanGaps(u);
  int active = 0;
  int open = 0;
  for (double g : g0) {
    active += std::isnan(g) ? 0 : 1;
    open += !std::isnan(g) && g > 0.0 ? 1 : 0;
  }
  ASSERT_GE(active, 3);
  ASSERT_GE(open, 1);
  ASSERT_LT(open, active);
  const double scale = tangent.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  const double h = 1e-6;
  double worstForce = 0.0;
  double worstGap = 0.0;
  for (Eigen::Index j = 0; j < u.size(); ++j) {
    Eigen::VectorXd up = u;
    Eigen::VectorXd down = u;
    up(j) += h;
    down(j) -= h;
    const Eigen::VectorXd fp = b.forces(up, nullptr);
    const std::vector<double> gp = b.constraint->meanGaps(up);
    const Eigen::VectorXd fm = b.forces(down, nullptr);
    const std::vector<double> gm = b.constraint->meanGaps(down);
    const Eigen::VectorXd numeric = -(fp - fm) / (2 * h);
    worstForce = std::max(worstForce, (numeric - tangent.col(j)).cwiseAbs().maxCoeff() / scale);
    // the mean-gap rows: the linearisation at u (paired again at u) against the exact gaps
    b.forces(u, nullptr);
    Eigen::VectorXd step = Eigen::VectorXd::Zero(u.size());
    step(j) = h;
    const std::vector<double> linear = b.constraint->meanGaps(u + step);
    for (std::size_t p = 0; p < g0.size(); ++p) {
      if (!std::isnan(g0[p])) {
        worstGap = std::max(worstGap, std::abs((gp[p] - gm[p]) / (2 * h) - (linear[p] - g0[p]) / h));
      }
    }
  }
  EXPECT_LT(worstForce, 1e-6) << "tangent against central differences, relative to its largest term";
  EXPECT_LT(worstGap, 1e-6) << "mean-gap rows against central differences";
  EXPECT_FALSE(b.constraint->symmetric());
}

TEST(LacGeometricTangent, Seg2PatchesPlaneStrain) {
  checkAgainstCentralDifferences({CellType::QUAD4, fem::Modelling::PlaneStrain, false});
}

TEST(LacGeometricTangent, Seg2PatchesCurrentJacobian) {
  checkAgainstCentralDifferences({CellType::QUAD4, fem::Modelling::PlaneStrain, true});
}

TEST(LacGeometricTangent, Seg2PatchesAxisymmetric) {
  checkAgainstCentralDifferences({CellType::QUAD4, fem::Modelling::Axisymmetric, false});
}

TEST(LacGeometricTangent, Seg3PatchesPlaneStrain) {
  checkAgainstCentralDifferences({CellType::QUAD8, fem::Modelling::PlaneStrain, false});
}

TEST(LacGeometricTangent, Seg3PatchesAxisymmetricCurrentJacobian) {
  checkAgainstCentralDifferences({CellType::QUAD8, fem::Modelling::Axisymmetric, true});
}

// LISSAGE='OUI': the averaged nodal normals depend on the neighbouring slave cells' nodes too
TEST(LacGeometricTangent, Seg2PatchesSmoothedNormals) {
  checkAgainstCentralDifferences({CellType::QUAD4, fem::Modelling::PlaneStrain, false, true});
}

TEST(LacGeometricTangent, Seg3PatchesSmoothedNormalsAxisymmetric) {
  checkAgainstCentralDifferences({CellType::QUAD8, fem::Modelling::Axisymmetric, true, true});
}

} // namespace
} // namespace stella::contact::lac
