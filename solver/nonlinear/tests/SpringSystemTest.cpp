// Discrete springs (AFFE_CARA_ELEM DISCRET / DISCRET_2D K_T_D_N on DIS_T / 2D_DIS_T POI1 cells)
// in the MechanicalSystem: a body held only by springs solved through the model / load /
// system layers against an exact rigid motion (forces k_i u(x_i) at the springs for a rigid
// u = t + w x x leave the body unstrained), the internal forces k u of the springs in
// equilibrium with the load (the Newton residual), and the user errors of AFFE_CARA_ELEM and of
// a discrete element left without stiffness.

#include "catalog/KeywordTree.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/assembly/tests/ElasticStudy.hpp"
#include "solver/inputs/ElementCharacteristicsReader.hpp"
#include "solver/nonlinear/ElasticSolve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace stella {
namespace {

struct SpringBody {
  fem::PlainMesh plain;
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::vector<NodeId> corners;
  std::vector<CellId> points; // POI1 cells on the corners
};

// A box of `type` cells with a POI1 cell on every corner node (group CORNERS).
SpringBody springBody(CellType type, const std::string& modelisation, const std::string& discrete) {
  SpringBody b;
  const bool threeD = dimension(type) == 3;
  b.plain = fem::boxMesh(type, {3, 2, threeD ? 2 : 1}, {1.5, 1.0, 1.0});
  b.mesh = std::make_shared<Mesh>();
  b.mesh->setDimension(b.plain.dimension);
  for (int n = 0; n < b.plain.nodeCount(); ++n) {
    Point3 x{0, 0, 0};
    int extremes = 0;
    const double size[3] = {1.5, 1.0, 1.0};
    for (int d = 0; d < b.plain.dimension; ++d) {
      x[static_cast<std::size_t>(d)] = b.plain.coordinates(n, d);
      const double v = b.plain.coordinates(n, d);
      extremes += (std::fabs(v) < 1e-12 || std::fabs(v - size[d]) < 1e-12) ? 1 : 0;
    }
    b.mesh->addNode(x);
    if (extremes == b.plain.dimension) {
      b.corners.push_back(n);
    }
  }
  std::vector<CellId> volumes;
  for (int c = 0; c < b.plain.cellCount(); ++c) {
    volumes.push_back(b.mesh->addCell(
        b.plain.cellType,
        std::span<const NodeId>(b.plain.cell(c), static_cast<std::size_t>(b.plain.nodesPerCell()))));
  }
  for (NodeId n : b.corners) {
    const NodeId one[] = {n};
    b.points.push_back(b.mesh->addCell(CellType::POI1, one));
  }
  b.mesh->setCellGroup("CORNERS", b.points);
  b.mesh->setNodeGroup("CORNERS", b.corners);
  b.model = std::make_shared<Model>(b.mesh);
  assignModelling(*b.model, volumes, modelisation, {});
  assignModelling(*b.model, b.points, discrete, {});
  finishModel(*b.model, {});
  return b;
}

std::string errorId(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.diagnostics().front().id;
  }
  return "none";
}

KeywordTree occurrence(std::vector<std::pair<std::string, ValueList>> simples) {
  KeywordTree t;
  for (auto& [name, v] : simples) {
    t.addSimple({name, v, {}, false});
  }
  return t;
}

ValueList reals(std::initializer_list<double> v) {
  ValueList out;
  for (double x : v) {
    out.push_back(Value(x));
  }
  return out;
}

ValueList text(const std::string& s) {
  return ValueList{Value(s)};
}

KeywordTree caraKeywords(const std::string& factor, const std::string& cara, ValueList vale) {
  KeywordTree kw;
  FactorKeyword f{
      factor,
      {occurrence({{"GROUP_MA", text("CORNERS")}, {"CARA", text(cara)}, {"VALE", std::move(vale)}})},
      {},
      false};
  kw.addFactor(f);
  return kw;
}

// The rigid motion u(x) = t + w x x of the exact-solution check (w along Z only in 2D).
Eigen::Vector3d rigidMotion(const Point3& x, int dim) {
  const Eigen::Vector3d t(0.01, -0.02, 0.015);
  const Eigen::Vector3d w =
      dim == 3 ? Eigen::Vector3d(0.004, -0.003, 0.005) : Eigen::Vector3d(0.0, 0.0, 0.005);
  Eigen::Vector3d u = t + w.cross(Eigen::Vector3d(x[0], x[1], x[2]));
  if (dim == 2) {
    u[2] = 0.0;
  }
  return u;
}

// Springs of different stiffness on every corner. (1) Forces k_i u(x_i) at the corners for a rigid
// motion u: u is the exact solution (no strain, each spring balances its force). (2) Forces on
// two nodes: the springs' forces k u balance the load, and the internal forces of the Newton
// residual equal the external forces.
void checkSpringHeldBody(CellType type, const std::string& modelisation, const std::string& discrete) {
  SpringBody b = springBody(type, modelisation, discrete);
  const int dim = b.model->components;
  auto cara = std::make_shared<ElementCharacteristics>();
  cara->model = b.model;
  for (std::size_t i = 0; i < b.points.size(); ++i) {
    const double s = 1.0 + static_cast<double>(i);
    cara->springs.push_back({b.points[i], b.corners[i], {40.0 * s, 70.0 + 5.0 * s, 90.0 / s}});
  }
  const double e = 1000.0;
  const double nu = 0.3;
  const std::vector<std::string> elas = testing::elasticEverywhere(*b.model);
  {
    auto rigid = std::make_shared<MechanicalLoad>();
    rigid->model = b.model;
    for (const auto& sp : cara->springs) {
      const Eigen::Vector3d u = rigidMotion(b.mesh->point(sp.node), dim);
      for (int c = 0; c < dim; ++c) {
        rigid->nodalForces.push_back({sp.node, c, sp.stiffness[static_cast<std::size_t>(c)] * u[c]});
      }
    }
    MechanicalSystem system(b.model, testing::elasticMaterialOn(b.mesh, e, nu),
                            {Excitation{rigid, nullptr, nullptr}}, elas, {}, cara);
    const StaticSolution s = ElasticSolve(system).solve(0.0, false);
    double error = 0.0;
    double scale = 0.0;
    for (NodeId n = 0; n < b.mesh->nodeCount(); ++n) {
      const Eigen::Vector3d exact = rigidMotion(b.mesh->point(n), dim);
      for (int c = 0; c < dim; ++c) {
        error = std::max(error, std::fabs(s.displacement(system.dofs().dof(n, c)) - exact[c]));
        scale = std::max(scale, std::fabs(exact[c]));
      }
    }
    EXPECT_GT(scale, 1e-3);
    EXPECT_LT(error, 1e-10 * scale);
  }
  auto load = std::make_shared<MechanicalLoad>();
  load->model = b.model;
  const NodeId loaded[2] = {b.corners.back(), static_cast<NodeId>(b.plain.nodeCount() / 2)};
  const double force[2][3] = {{3.0, -2.0, 1.5}, {-1.0, 4.0, 2.5}};
  for (int i = 0; i < 2; ++i) {
    for (int c = 0; c < dim; ++c) {
      load->nodalForces.push_back({loaded[i], c, force[i][c]});
    }
  }
  MechanicalSystem system(b.model, testing::elasticMaterialOn(b.mesh, e, nu),
                          {Excitation{load, nullptr, nullptr}}, elas, {}, cara);
  ElasticSolve solver(system);
  const StaticSolution s = solver.solve(0.0, false);

  // Resultant of the spring forces = - applied resultant (global equilibrium).
  for (int c = 0; c < dim; ++c) {
    double springs = 0.0;
    for (const auto& sp : cara->springs) {
      springs += sp.stiffness[static_cast<std::size_t>(c)] * s.displacement(system.dofs().dof(sp.node, c));
    }
    EXPECT_NEAR(springs, force[0][c] + force[1][c], 1e-10);
  }
  // The residual at the converged state, reached in two increments as Newton does: the volume
  // cells integrate the stress from the state at the start of the increment, the springs take
  // k (uStart + du); internal forces = loads.
  const int n = system.dofs().physicalCount();
  const PointState zero = zeroPointState(system.model(), system.behaviours().maxInternalVariables());
  const Eigen::VectorXd half = 0.5 * s.displacement;
  PointState middle = zero;
  system.assembler().run(Eigen::VectorXd::Zero(n), half, zero, behaviour::Option::Full,
                         {nullptr, nullptr, &middle});
  Eigen::VectorXd fint = Eigen::VectorXd::Zero(n);
  system.assembler().run(half, half, middle, behaviour::Option::Full, {nullptr, &fint, nullptr});
  const Eigen::VectorXd fext = system.externalForces(0.0);
  EXPECT_LT((fint - fext).cwiseAbs().maxCoeff(), 1e-10 * fext.cwiseAbs().maxCoeff());
}

TEST(SpringSystem, ThreeDimensionalBodyHeldOnlyBySpringsMovesRigidlyAndBalancesTheLoad) {
  checkSpringHeldBody(CellType::HEXA8, "3D", "DIS_T");
}

TEST(SpringSystem, PlaneStrainBodyHeldOnlyBySpringsMovesRigidlyAndBalancesTheLoad) {
  checkSpringHeldBody(CellType::QUAD4, "D_PLAN", "2D_DIS_T");
}

TEST(SpringSystem, AffeCaraElemReadsStiffnessesAndRefusesWhatIsNotImplemented) {
  SpringBody b = springBody(CellType::HEXA8, "3D", "DIS_T");
  ElementCharacteristics cara;
  cara.model = b.model;
  readElementCharacteristics(caraKeywords("DISCRET", "K_T_D_N", reals({1.0, 2.0, 3.0})), cara);
  ASSERT_EQ(cara.springs.size(), 8u);
  EXPECT_EQ(cara.springs[0].cell, b.points[0]);
  EXPECT_EQ(cara.springs[0].node, b.corners[0]);
  EXPECT_DOUBLE_EQ(cara.springs[5].stiffness[2], 3.0);
  // Masses and beams: refused by name; wrong VALE count; negative stiffness; 2D keyword on 3D.
  EXPECT_EQ(
      errorId([&] { readElementCharacteristics(caraKeywords("DISCRET", "M_T_D_N", reals({1.0})), cara); }),
      "CARA_1");
  EXPECT_EQ(errorId([&] {
              KeywordTree kw;
              kw.addFactor({"POUTRE", {occurrence({{"GROUP_MA", text("CORNERS")}})}, {}, false});
              readElementCharacteristics(kw, cara);
            }),
            "CARA_1");
  EXPECT_EQ(errorId([&] {
              readElementCharacteristics(caraKeywords("DISCRET", "K_T_D_N", reals({1.0, 2.0})), cara);
            }),
            "CARA_2");
  EXPECT_EQ(errorId([&] {
              readElementCharacteristics(caraKeywords("DISCRET", "K_T_D_N", reals({1.0, -2.0, 1.0})), cara);
            }),
            "CARA_4");
  EXPECT_EQ(errorId([&] {
              readElementCharacteristics(caraKeywords("DISCRET_2D", "K_T_D_N", reals({1.0, 2.0})), cara);
            }),
            "CARA_3");
}

TEST(SpringSystem, DiscreteElementWithoutStiffnessIsAUserError) {
  SpringBody b = springBody(CellType::QUAD4, "D_PLAN", "2D_DIS_T");
  auto materials = testing::elasticMaterialOn(b.mesh, 1000.0, 0.3);
  const std::vector<std::string> elas(b.model->cells.size(), "ELAS");
  EXPECT_EQ(errorId([&] { MechanicalSystem system(b.model, materials, {}, elas, {}); }), "CARA_5");
  auto cara = std::make_shared<ElementCharacteristics>();
  cara->model = b.model;
  cara->springs.push_back({b.points[0], b.corners[0], {1.0, 1.0, 0.0}});
  EXPECT_EQ(errorId([&] { MechanicalSystem system(b.model, materials, {}, elas, {}, cara); }), "CARA_5");
  SpringBody other = springBody(CellType::QUAD4, "D_PLAN", "2D_DIS_T");
  auto foreign = std::make_shared<ElementCharacteristics>();
  foreign->model = other.model;
  EXPECT_EQ(errorId([&] { MechanicalSystem system(b.model, materials, {}, elas, {}, foreign); }), "CARA_6");
}

} // namespace
} // namespace stella
