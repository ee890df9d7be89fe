// The contact constraints of STAT_NON_LINE method by method on a toy system: two unit squares
// (one QUAD4 each) 0.1 apart, every DOF held by a grounded spring of stiffness k (K = k I), the
// two slave nodes of the upper square pushed down. Closed forms: a slave node and its master
// node (matching, weight 1) pushed by F close the gap g when F > k g and then carry
// lambda = (F - k g) / 2.

#include "solver/contact/DualContactConstraint.hpp"
#include "solver/contact/PenaltyContactConstraint.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"
#include "solver/database/Result.hpp"
#include "solver/nonlinear/SaddleSolver.hpp"

#include <gtest/gtest.h>

#include <sstream>

namespace stella::contact {
namespace {

constexpr double kGap = 0.1;
constexpr double kSpring = 100.0;

struct Toy {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::unique_ptr<DofMap> dofs;
  std::shared_ptr<ContactDefinition> definition;

  explicit Toy(ContactAlgorithm algorithm) {
    mesh = std::make_shared<Mesh>(testing::twoBlocks(CellType::QUAD4, 1, 1, kGap));
    model = std::make_shared<Model>(mesh);
    model->components = 2;
    model->activeNodes.assign(static_cast<std::size_t>(mesh->nodeCount()), true);
    dofs = std::make_unique<DofMap>(*model);
    definition = std::make_shared<ContactDefinition>();
    definition->mesh = mesh;
    ContactZone zone;
    zone.masterGroup = "A_YMAX";
    zone.slaveGroup = "B_YMIN";
    zone.algorithm = algorithm;
    zone.normalPenalty = 1.0e6;
    definition->zones.push_back(zone);
  }
  int n() const { return dofs->physicalCount(); }
  std::vector<NodeId> slaves() const { return zoneSlaveNodes(*mesh, definition->zones[0]); }
  // Downward force F on the slave nodes.
  Eigen::VectorXd load(double f) const {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n());
    for (NodeId s : slaves()) {
      r(dofs->dof(s, 1)) = -f;
    }
    return r;
  }
};

TEST(ContactRows, GapGradientOnMatchingNodes) {
  Toy toy(ContactAlgorithm::Constraint);
  const auto links = pairAll(*toy.definition, meshPositions(*toy.mesh, nullptr));
  ASSERT_EQ(links.size(), 2u);
  const LinkRows rows = buildLinkRows(links, *toy.dofs, {true}, {}, true);
  ASSERT_EQ(rows.problem.A.rows(), 2);
  for (Eigen::Index i = 0; i < 2; ++i) {
    EXPECT_NEAR(rows.problem.gap(i), kGap, 1e-12);
    const ContactLink& l = links[static_cast<std::size_t>(rows.link[static_cast<std::size_t>(i)])];
    // +1 on the slave DY, -1 on the master node under it (the other master node has weight 0)
    EXPECT_NEAR(rows.problem.A.coeff(i, toy.dofs->dof(l.slave, 1)), 1.0, 1e-12);
    double masterSum = 0.0;
    for (NodeId m : l.masterNodes) {
      masterSum += rows.problem.A.coeff(i, toy.dofs->dof(m, 1));
    }
    EXPECT_NEAR(masterSum, -1.0, 1e-12);
    EXPECT_NEAR(rows.problem.A.row(i).sum(), 0.0, 1e-12); // no x components on a flat face
    EXPECT_NEAR(std::abs(rows.friction.T1.row(i).sum()), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(rows.friction.T1.coeff(i, toy.dofs->dof(l.slave, 0))), 1.0, 1e-12);
  }
  EXPECT_EQ(rows.friction.T2.rows(), 0); // 2D
  // a zone that is only measured has no row
  EXPECT_EQ(buildLinkRows(links, *toy.dofs, {false}, {}, false).problem.A.rows(), 0);
}

class DualToy : public ::testing::TestWithParam<ContactAlgorithm> {};

TEST_P(DualToy, CorrectionGivesTheClosedFormThenTheGeometricLoopAccepts) {
  Toy toy(GetParam());
  toy.definition->settings.gcpTolerance = 1e-12;
  DualContactConstraint c(toy.definition, *toy.dofs, GetParam());
  c.initialize();
  SaddleSolver solver(*toy.dofs, *toy.mesh, {}, std::vector<bool>(static_cast<std::size_t>(toy.n()), false));
  Eigen::SparseMatrix<double> k(toy.n(), toy.n());
  k.setIdentity();
  k *= kSpring;
  solver.factorize(k, true, c.symmetric());
  const double f = 30.0; // F/k = 0.3 > g: contact, lambda = (30 - 10) / 2 = 10
  Eigen::VectorXd u = Eigen::VectorXd::Zero(toy.n());
  c.beginStep(u, 1.0);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(toy.n());
  std::vector<Eigen::Triplet<double>> tangent;
  c.addForces(u, forces, &tangent);
  EXPECT_EQ(forces.norm(), 0.0);
  EXPECT_TRUE(tangent.empty()); // dual methods add no stiffness
  Eigen::VectorXd ddu;
  Eigen::VectorXd dl;
  solver.solve(toy.load(f) + forces, Eigen::VectorXd(), Eigen::VectorXd::Zero(toy.n()), ddu, dl);
  c.correct(u, ddu, dl, solver);
  u += ddu;
  for (NodeId s : toy.slaves()) {
    EXPECT_NEAR(u(toy.dofs->dof(s, 1)), (-f + 10.0) / kSpring, 1e-10);
  }
  // The next residual includes the contact forces: K u = F + A^T mu exactly.
  forces.setZero();
  c.addForces(u, forces, nullptr);
  EXPECT_NEAR((kSpring * u - toy.load(f) - forces).cwiseAbs().maxCoeff(), 0.0, 1e-9);
  EXPECT_NEAR(forces.sum(), 0.0, 1e-9); // action and reaction
  for (double mu : c.linkForces()) {
    EXPECT_NEAR(mu, 10.0, 1e-9);
  }
  // Converged: the contact nodes moved since the pairing, so the loop pairs again once...
  EXPECT_FALSE(c.acceptConvergence(u));
  EXPECT_EQ(c.pairings(), 3); // initial, step start, geometric update
  // ...and accepts when they no longer move.
  Eigen::VectorXd again = Eigen::VectorXd::Zero(toy.n());
  solver.solve(
      toy.load(f) +
          [&] {
            Eigen::VectorXd fr = Eigen::VectorXd::Zero(toy.n());
            c.addForces(u, fr, nullptr);
            return fr;
          }() -
          kSpring * u,
      Eigen::VectorXd(), Eigen::VectorXd::Zero(toy.n()), again, dl);
  c.correct(u, again, dl, solver);
  EXPECT_LT(again.cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_TRUE(c.acceptConvergence(u + again));
  EXPECT_EQ(c.activeLinks(), 2);
  EXPECT_EQ(c.geometricIterations(), 2);
  EXPECT_LT(c.maxInterpenetration(), 1e-10);
  std::ostringstream report;
  c.reportStep(report);
  EXPECT_NE(report.str().find("Nombre de liaisons de contact : 2"), std::string::npos);
  ResultStep step;
  c.store(step);
  const Field* cont = step.field("CONT_NOEU");
  ASSERT_NE(cont, nullptr);
  for (NodeId s : toy.slaves()) {
    EXPECT_EQ(cont->value(static_cast<std::size_t>(s), 0), 2.0);          // CONT
    EXPECT_NEAR(cont->value(static_cast<std::size_t>(s), 1), 0.0, 1e-10); // JEU
    EXPECT_NEAR(cont->value(static_cast<std::size_t>(s), 2), 10.0, 1e-9); // RN
    EXPECT_NEAR(cont->value(static_cast<std::size_t>(s), 4), 10.0, 1e-9); // RNY
  }
  EXPECT_NE(c.singularNote().find("GROUP_MA_ESCL='B_YMIN'"), std::string::npos);
  EXPECT_NE(c.effects().find(algorithmName(GetParam())), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Algorithms, DualToy,
                         ::testing::Values(ContactAlgorithm::Constraint, ContactAlgorithm::Gcp));

TEST(PenaltyToy, ForcesAndTangentOfThePenalty) {
  Toy toy(ContactAlgorithm::Penalty);
  PenaltyContactConstraint c(toy.definition, *toy.dofs, std::nullopt);
  c.initialize();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(toy.n());
  c.beginStep(u, 1.0);
  // slave nodes 0.1 + 1e-4 down: interpenetration 1e-4, force E_N x 1e-4 = 100 each
  for (NodeId s : toy.slaves()) {
    u(toy.dofs->dof(s, 1)) = -kGap - 1e-4;
  }
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(toy.n());
  std::vector<Eigen::Triplet<double>> tangent;
  c.addForces(u, forces, &tangent);
  EXPECT_TRUE(c.symmetric());
  for (NodeId s : toy.slaves()) {
    EXPECT_NEAR(forces(toy.dofs->dof(s, 1)), 100.0, 1e-6);
  }
  EXPECT_NEAR(forces.sum(), 0.0, 1e-9);
  Eigen::SparseMatrix<double> t(toy.n(), toy.n());
  t.setFromTriplets(tangent.begin(), tangent.end());
  const NodeId s = toy.slaves().front();
  EXPECT_NEAR(t.coeff(toy.dofs->dof(s, 1), toy.dofs->dof(s, 1)), 1.0e6, 1e-6); // E_N
  // no correction
  Eigen::VectorXd ddu = Eigen::VectorXd::Ones(toy.n());
  Eigen::VectorXd dl;
  SaddleSolver solver(*toy.dofs, *toy.mesh, {}, std::vector<bool>(static_cast<std::size_t>(toy.n()), false));
  c.correct(u, ddu, dl, solver);
  EXPECT_EQ(ddu, Eigen::VectorXd::Ones(toy.n()));
}

TEST(PenaltyToy, AdaptCoefPenaRaisesTheStiffnessUntilPeneMaxi) {
  Toy toy(ContactAlgorithm::Penalty);
  FailurePolicy policy;
  policy.event = FailurePolicy::Event::Interpenetration;
  policy.action = FailurePolicy::Action::AdaptPenalty;
  policy.maxPenetration = 1e-5;
  policy.maxCoefficient = 1e8;
  PenaltyContactConstraint c(toy.definition, *toy.dofs, policy);
  c.initialize();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(toy.n());
  c.beginStep(u, 1.0);
  for (NodeId s : toy.slaves()) {
    u(toy.dofs->dof(s, 1)) = -kGap - 1e-4;
  }
  EXPECT_FALSE(c.acceptConvergence(u)); // 1e-4 > PENE_MAXI: E_N x 10
  EXPECT_DOUBLE_EQ(c.penaltyFactor(), 10.0);
  EXPECT_FALSE(c.acceptConvergence(u)); // x 100 = COEF_MAXI
  EXPECT_DOUBLE_EQ(c.penaltyFactor(), 100.0);
  // E_N at COEF_MAXI: accepted with an alarm (the geometric loop pairs first: contact nodes moved)
  EXPECT_FALSE(c.acceptConvergence(u));
  EXPECT_TRUE(c.acceptConvergence(u));
  std::ostringstream report;
  c.reportStep(report);
  EXPECT_NE(report.str().find("CONTACT_15"), std::string::npos);
}

} // namespace
} // namespace stella::contact
