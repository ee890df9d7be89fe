// Coulomb friction of the continuous formulation at integration points (ContinuousPointContact.hpp),
// in 3D, checked by central finite differences of the quantities the Newton iterations linearise:
//   the tangent the constraint assembles (K = -d forces/du at fixed multipliers), the rows of the
//   multipliers' equations (B = dE/du), their block M = -dE/dLambda and the force columns
//   C = -d forces/dLambda (LAGS_C and the two components of LAGS_F on each slave node);
// on a tilted flat master (QUAD4) under a slave face sunk into it and moved tangentially (QUAD4,
// TRIA3, QUAD8, TRIA6 slave cells at their Gauss points), with ALGO_FROT STANDARD and PENALISATION,
// every point sticking, then every point sliding (the turn of the sliding direction: the tangent
// w rho_t alpha F^T P F and the row alpha P F), with the threshold following LAGS_C
// (ALGO_RESO_FROT='NEWTON'). Dropping the sliding turn's tangent makes the sliding cases fail
// (checked when writing the test: relative error on K 6e-2 to 4e-1 instead of < 5e-9).

#include "solver/assembly/DofMap.hpp"
#include "solver/contact/ContinuousPointContact.hpp"
#include "solver/model/Model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <iostream>

namespace stella::contact {
namespace {

struct PointAssembly {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::unique_ptr<DofMap> dofs;
  std::shared_ptr<ContactDefinition> definition;

  static double plane(double x, double y) { return 0.1 * x - 0.05 * y; }

  PointAssembly(CellType slaveType, bool penalisedFriction) {
    mesh = std::make_shared<Mesh>();
    mesh->setDimension(3);
    std::vector<NodeId> quad;
    for (const auto& [x, y] :
         std::array<std::pair<double, double>, 4>{{{-1, -1}, {2, -1}, {2, 2}, {-1, 2}}}) {
      quad.push_back(mesh->addNode({x, y, plane(x, y)}));
    }
    const CellId master = mesh->addCell(CellType::QUAD4, quad);
    // the slave face 0.01 below the master plane (penetrating), its normal -z (facing the master)
    std::vector<std::pair<double, double>> xy;
    switch (slaveType) {
    case CellType::TRIA3:
      xy = {{0, 0}, {0, 1}, {1, 0}};
      break;
    case CellType::TRIA6:
      xy = {{0, 0}, {0, 1}, {1, 0}, {0, 0.5}, {0.5, 0.5}, {0.5, 0}};
      break;
    case CellType::QUAD8:
      xy = {{0, 0}, {0, 1}, {1, 1}, {1, 0}, {0, 0.5}, {0.5, 1}, {1, 0.5}, {0.5, 0}};
      break;
    default:
      xy = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    }
    std::vector<NodeId> face;
    for (const auto& [x, y] : xy) {
      face.push_back(mesh->addNode({x, y, plane(x, y) - 0.01}));
    }
    const CellId slave = mesh->addCell(slaveType, face);
    mesh->setCellGroup("MAIT", {master});
    mesh->setCellGroup("ESCL", {slave});
    model = std::make_shared<Model>(mesh);
    model->components = 3;
    model->activeNodes.assign(static_cast<std::size_t>(mesh->nodeCount()), true);
    dofs = std::make_unique<DofMap>(*model);
    definition = std::make_shared<ContactDefinition>();
    definition->mesh = mesh;
    definition->settings.formulation = Formulation::Continue;
    definition->settings.friction = true;
    ContactZone zone;
    zone.masterGroup = "MAIT";
    zone.slaveGroup = "ESCL";
    zone.algorithm = ContactAlgorithm::Standard;
    zone.friction = true;
    zone.coulomb = 0.3;
    zone.continuous.augmentation = 50.0;
    zone.continuous.frictionAugmentation = 20.0;
    zone.continuous.frictionPenalised = penalisedFriction;
    zone.continuous.frictionPenalty = 20.0;
    zone.continuous.init = ContactInit::Yes;
    zone.continuous.integration = ContactIntegration::Gauss;
    zone.continuous.integrationOrder = slaveType == CellType::TRIA6 ? 5 : 3; // at least a point per node
    definition->zones.push_back(zone);
  }
};

Eigen::MatrixXd dense(const std::vector<Eigen::Triplet<double>>& t, Eigen::Index n) {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (const auto& e : t) {
    k(e.row(), e.col()) += e.value();
  }
  return k;
}

double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& fd) {
  const double scale = fd.cwiseAbs().maxCoeff();
  return scale > 0.0 ? (a - fd).cwiseAbs().maxCoeff() / scale : (a - fd).cwiseAbs().maxCoeff();
}

struct FrictionCase {
  CellType slave;
  bool penalised;
  bool sliding;
};

std::string caseName(const FrictionCase& c) {
  return fmt::format("{} {} {}", name(c.slave), c.penalised ? "PENALISATION" : "STANDARD",
                     c.sliding ? "sliding" : "sticking");
}

class PointFrictionTangent : public ::testing::TestWithParam<FrictionCase> {};

TEST_P(PointFrictionTangent, MatchesFiniteDifferences) {
  const FrictionCase fc = GetParam();
  PointAssembly a(fc.slave, fc.penalised);
  const auto n = static_cast<Eigen::Index>(a.dofs->physicalCount());
  ContinuousPointContactConstraint c(a.definition, *a.dofs, fem::Modelling::ThreeD);
  c.initialize();
  const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(n);
  c.beginStep(u0, 1.0);
  // a tangential motion of the slave face (a slip of about 1e-3, turning from point to point) and a
  // general small motion of every node
  Eigen::VectorXd u(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    u(i) = 1e-4 * std::sin(1.7 * static_cast<double>(i) + 0.3);
  }
  // (penalised sliding: 0.1, so that COEF_PENA_FROT times the slip is beyond the threshold)
  const double slip = fc.penalised && fc.sliding ? 0.1 : 1e-3;
  for (NodeId node : a.mesh->cellNodes(a.mesh->cellGroup("ESCL")->front())) {
    const Point3 x = a.mesh->point(node);
    u(a.dofs->dof(node, 0)) += slip * (1.0 + 0.3 * x[1]);
    u(a.dofs->dof(node, 1)) += slip * (0.5 - 0.4 * x[0]);
  }
  // compressed nodes (LAGS_C < 0); LAGS_F small (every point sticks: |q| < mu |lambda|) or large
  // (every point slides, along directions turning with the slip)
  Eigen::VectorXd lambda = c.multipliers();
  const Eigen::Index nm = fc.penalised ? lambda.size() : lambda.size() / 3;
  for (Eigen::Index i = 0; i < lambda.size(); ++i) {
    lambda(i) = i < nm ? -1.0 - 0.1 * static_cast<double>(i)
                       : (fc.sliding ? 1.0 : 0.002) * std::cos(0.9 * static_cast<double>(i));
  }
  c.setMultipliers(lambda);
  const auto forcesAt = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    c.linearisation(v); // the statuses of v
    c.addForces(v, f, nullptr);
    return f;
  };
  const ContinuousPointContactConstraint::Linearisation lin = c.linearisation(u);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::Triplet<double>> t;
  c.addForces(u, f, &t);
  const Eigen::MatrixXd k = dense(t, n);
  constexpr double h = 1e-8;
  Eigen::MatrixXd kfd(n, n);
  Eigen::MatrixXd bfd(lambda.size(), n);
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::VectorXd up = u;
    Eigen::VectorXd um = u;
    up(j) += h;
    um(j) -= h;
    kfd.col(j) = -(forcesAt(up) - forcesAt(um)) / (2.0 * h);
    bfd.col(j) = (c.linearisation(up).residual - c.linearisation(um).residual) / (2.0 * h);
  }
  Eigen::MatrixXd mfd(lambda.size(), lambda.size());
  Eigen::MatrixXd cfd(lambda.size(), n);
  for (Eigen::Index j = 0; j < lambda.size(); ++j) {
    Eigen::VectorXd lp = lambda;
    Eigen::VectorXd lm = lambda;
    lp(j) += h;
    lm(j) -= h;
    c.setMultipliers(lp);
    const Eigen::VectorXd ep = c.linearisation(u).residual;
    const Eigen::VectorXd fp = forcesAt(u);
    c.setMultipliers(lm);
    const Eigen::VectorXd em = c.linearisation(u).residual;
    const Eigen::VectorXd fm = forcesAt(u);
    mfd.col(j) = -(ep - em) / (2.0 * h);
    cfd.row(j) = (-(fp - fm) / (2.0 * h)).transpose();
  }
  c.setMultipliers(lambda);
  // the case is what it says: sliding points (and only they) couple the force to LAGS_C beyond the
  // normal row (the threshold's column, ALGO_RESO_FROT='NEWTON')
  const double coupling = (lin.column - lin.row).topRows(nm).cwiseAbs().maxCoeff();
  EXPECT_EQ(coupling > 0.0, fc.sliding) << caseName(fc) << ": " << coupling;
  const double ek = relativeError(k, kfd);
  const double eb = lambda.size() > 0 ? relativeError(lin.row, bfd) : 0.0;
  const double em = relativeError(lin.mass, mfd);
  const double ec = relativeError(lin.column, cfd);
  std::cout << fmt::format("[ point friction ] {}: K {:.1e}, B {:.1e}, M {:.1e}, C {:.1e} (max |K| {:.2e})\n",
                           caseName(fc), ek, eb, em, ec, kfd.cwiseAbs().maxCoeff());
  EXPECT_GT(kfd.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LT(ek, 1e-6) << caseName(fc);
  EXPECT_LT(eb, 1e-6) << caseName(fc);
  EXPECT_LT(em, 1e-6) << caseName(fc);
  EXPECT_LT(ec, 1e-6) << caseName(fc);
}

std::vector<FrictionCase> frictionCases() {
  std::vector<FrictionCase> out;
  for (CellType t : {CellType::QUAD4, CellType::TRIA3, CellType::QUAD8, CellType::TRIA6}) {
    for (bool penalised : {false, true}) {
      for (bool sliding : {false, true}) {
        out.push_back({t, penalised, sliding});
      }
    }
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(SlaveCellsAndAlgorithms, PointFrictionTangent, ::testing::ValuesIn(frictionCases()),
                         [](const ::testing::TestParamInfo<FrictionCase>& param) {
                           std::string s = caseName(param.param);
                           for (char& ch : s) {
                             ch = ch == ' ' ? '_' : ch;
                           }
                           return s;
                         });

} // namespace
} // namespace stella::contact
