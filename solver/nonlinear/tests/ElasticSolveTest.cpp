// Linear static solves through the model / load / system layers on meshes built in C++:
// a constant-stress patch test with imposed linear displacements on distorted meshes, a bar in
// tension by pressure against the closed form, the same bar with eliminated (AFFE_CHAR_CINE)
// conditions, and a singular model whose error names a free node and component.

#include "solver/nonlinear/ElasticSolve.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/assembly/tests/ElasticStudy.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/model/ModelBuilder.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella {
namespace {

std::shared_ptr<Mesh> toMesh(fem::PlainMesh p, bool distort) {
  for (int n = 0; distort && n < p.nodeCount(); ++n) {
    auto x = p.coordinates.row(n);
    bool interior = true;
    for (int d = 0; d < p.dimension; ++d) {
      interior = interior && x(d) > 1e-9 && x(d) < 1.0 - 1e-9;
    }
    if (interior) { // a smooth perturbation keeps cells valid
      const double z = p.dimension == 3 ? x(2) : 0.0;
      const double dx = 0.03 * std::sin(7.0 * x(0) + 3.0 * x(1));
      const double dy = 0.03 * std::cos(5.0 * x(0) - 4.0 * x(1) + z);
      x(0) += dx;
      x(1) += dy;
    }
  }
  return fem::toMesh(p);
}

using testing::elasticMaterialOn;
using testing::modelOn;

bool onBoundary(const Point3& x, int dim) {
  for (int d = 0; d < dim; ++d) {
    if (std::fabs(x[static_cast<std::size_t>(d)]) < 1e-12 ||
        std::fabs(x[static_cast<std::size_t>(d)] - 1.0) < 1e-12) {
      return true;
    }
  }
  return false;
}

// u = A x with a constant gradient A: every boundary node imposed (DDL_IMPO), interior free.
struct PatchCase {
  CellType type;
  std::string modelisation;
};

class PatchTest : public ::testing::TestWithParam<PatchCase> {};

TEST_P(PatchTest, ImposedLinearDisplacementGivesExactConstantStress) {
  const auto& pc = GetParam();
  const bool threeD = dimension(pc.type) == 3;
  auto mesh = toMesh(fem::boxMesh(pc.type, {3, 3, threeD ? 2 : 1}, {1.0, 1.0, 1.0}), true);
  auto model = modelOn(mesh, pc.modelisation);
  const int dim = model->components;
  const double a[3][3] = {{1.0e-3, 2.0e-4, -1.0e-4}, {-3.0e-4, 5.0e-4, 2.0e-4}, {1.0e-4, 3.0e-4, -2.0e-4}};
  auto load = std::make_shared<MechanicalLoad>();
  load->model = model;
  for (NodeId n = 0; n < mesh->nodeCount(); ++n) {
    const Point3 x = mesh->point(n);
    if (!onBoundary(x, dim)) {
      continue;
    }
    for (int i = 0; i < dim; ++i) {
      double v = 0.0;
      for (int j = 0; j < dim; ++j) {
        v += a[i][j] * x[static_cast<std::size_t>(j)];
      }
      load->relations.push_back({{{n, i, 1.0}}, v, "DDL_IMPO"});
    }
  }
  const double e = 2.0e5;
  const double nu = 0.3;
  MechanicalSystem system(model, elasticMaterialOn(mesh, e, nu), {Excitation{load, nullptr, nullptr}},
                          std::vector<std::string>(model->cells.size(), "ELAS"), {});
  ElasticSolve solver(system);
  const StaticSolution s = solver.solve(0.0, true);
  double maxError = 0.0;
  double scale = 0.0;
  for (NodeId n = 0; n < mesh->nodeCount(); ++n) {
    const Point3 x = mesh->point(n);
    for (int i = 0; i < dim; ++i) {
      double exact = 0.0;
      for (int j = 0; j < dim; ++j) {
        exact += a[i][j] * x[static_cast<std::size_t>(j)];
      }
      maxError = std::max(maxError, std::fabs(s.displacement(system.dofs().dof(n, i)) - exact));
      scale = std::max(scale, std::fabs(exact));
    }
  }
  EXPECT_LT(maxError, 1e-10 * scale);
  // Stress: D eps with eps from A (plane strain / 3D); sigma_xx checked with the closed form.
  const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu = e / (2 * (1 + nu));
  double trace = a[0][0] + a[1][1] + (threeD ? a[2][2] : 0.0);
  const double sxx = lambda * trace + 2 * mu * a[0][0];
  const double sxy = mu * (a[0][1] + a[1][0]);
  const Field& sig = s.state.stress;
  double stressError = 0.0;
  for (std::size_t p = 0; p < sig.entityCount(); ++p) {
    stressError = std::max(stressError, std::fabs(sig.value(p, 0) - sxx));
    stressError = std::max(stressError, std::fabs(sig.value(p, 3) - sxy));
  }
  EXPECT_LT(stressError, 1e-10 * std::fabs(sxx));
  EXPECT_GT(sig.entityCount(), 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Cells, PatchTest,
    ::testing::Values(PatchCase{CellType::QUAD4, "D_PLAN"}, PatchCase{CellType::QUAD8, "D_PLAN"},
                      PatchCase{CellType::TRIA3, "D_PLAN"}, PatchCase{CellType::TRIA6, "D_PLAN"},
                      PatchCase{CellType::HEXA8, "3D"}, PatchCase{CellType::HEXA20, "3D"},
                      PatchCase{CellType::TETRA4, "3D"}, PatchCase{CellType::TETRA10, "3D"}));

// Bar [0,1]^2, D_PLAN, DX = 0 on x = 0, DY = 0 at the origin, pressure -p on x = 1 (tension).
struct Bar {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::vector<NodeId> left;
  NodeId origin = -1;
  NodeId corner = -1; // (1, 1)
};

Bar makeBar() {
  Bar b;
  b.mesh = toMesh(fem::boxMesh(CellType::QUAD4, {4, 2, 1}, {1.0, 1.0, 1.0}), false);
  std::vector<std::pair<double, NodeId>> right;
  for (NodeId n = 0; n < b.mesh->nodeCount(); ++n) {
    const Point3 x = b.mesh->point(n);
    if (x[0] < 1e-12) {
      b.left.push_back(n);
      if (x[1] < 1e-12) {
        b.origin = n;
      }
    }
    if (x[0] > 1.0 - 1e-12) {
      right.emplace_back(x[1], n);
      if (x[1] > 1.0 - 1e-12) {
        b.corner = n;
      }
    }
  }
  std::sort(right.begin(), right.end());
  std::vector<CellId> edges;
  for (std::size_t i = 0; i + 1 < right.size(); ++i) {
    const NodeId nodes[2] = {right[i].second, right[i + 1].second};
    edges.push_back(b.mesh->addCell(CellType::SEG2, nodes));
  }
  b.mesh->setCellGroup("RIGHT", edges);
  b.model = modelOn(b.mesh, "D_PLAN");
  return b;
}

TEST(ElasticSolve, BarInTensionByPressureMatchesClosedFormAndReactions) {
  Bar b = makeBar();
  auto load = std::make_shared<MechanicalLoad>();
  load->model = b.model;
  for (NodeId n : b.left) {
    load->relations.push_back({{{n, 0, 1.0}}, 0.0, "DDL_IMPO"});
  }
  load->relations.push_back({{{b.origin, 1, 1.0}}, 0.0, "DDL_IMPO"});
  const double p = 10.0;
  for (CellId c : *b.mesh->cellGroup("RIGHT")) {
    load->pressures.push_back({c, -p});
  }
  const double e = 1000.0;
  const double nu = 0.25;
  MechanicalSystem system(b.model, elasticMaterialOn(b.mesh, e, nu), {Excitation{load, nullptr, nullptr}},
                          std::vector<std::string>(b.model->cells.size(), "ELAS"), {});
  ElasticSolve solver(system);
  const StaticSolution s = solver.solve(0.0, true);
  // Plane strain, sigma_xx = p, sigma_yy = 0: eps_xx = (1 - nu^2) p / E, eps_yy = -nu (1 + nu) p / E.
  EXPECT_NEAR(s.displacement(system.dofs().dof(b.corner, 0)), (1 - nu * nu) * p / e, 1e-13);
  EXPECT_NEAR(s.displacement(system.dofs().dof(b.corner, 1)), -nu * (1 + nu) * p / e, 1e-13);
  for (std::size_t q = 0; q < s.state.stress.entityCount(); ++q) {
    EXPECT_NEAR(s.state.stress.value(q, 0), p, 1e-10);
    EXPECT_NEAR(s.state.stress.value(q, 1), 0.0, 1e-10);
    EXPECT_NEAR(s.state.stress.value(q, 2), nu * p, 1e-10);
  }
  // The multipliers are the support reactions: they balance the applied force p * 1.
  double sum = 0.0;
  for (int r = 0; r < static_cast<int>(b.left.size()); ++r) {
    sum += s.multipliers(r);
  }
  EXPECT_NEAR(sum, p, 1e-10);
}

TEST(ElasticSolve, EliminatedConditionsGiveTheSameDisplacement) {
  Bar b = makeBar();
  auto kin = std::make_shared<KinematicLoad>();
  kin->model = b.model;
  for (NodeId n : b.left) {
    kin->imposed.push_back({n, 0, 0.0});
  }
  kin->imposed.push_back({b.origin, 1, 0.0});
  auto load = std::make_shared<MechanicalLoad>();
  load->model = b.model;
  load->nodalForces.push_back({b.corner, 0, 1.0});
  MechanicalSystem system(b.model, elasticMaterialOn(b.mesh, 1000.0, 0.25),
                          {Excitation{nullptr, kin, nullptr}, Excitation{load, nullptr, nullptr}},
                          std::vector<std::string>(b.model->cells.size(), "ELAS"), {});
  ElasticSolve solver(system);
  const StaticSolution s = solver.solve(0.0, false);
  EXPECT_GT(s.displacement(system.dofs().dof(b.corner, 0)), 0.0);
  for (NodeId n : b.left) {
    EXPECT_EQ(s.displacement(system.dofs().dof(n, 0)), 0.0);
  }
  // Same problem dualised: same displacement.
  auto dual = std::make_shared<MechanicalLoad>();
  dual->model = b.model;
  for (const auto& d : kin->imposed) {
    dual->relations.push_back({{{d.node, d.component, 1.0}}, d.value, "DDL_IMPO"});
  }
  MechanicalSystem system2(b.model, elasticMaterialOn(b.mesh, 1000.0, 0.25),
                           {Excitation{dual, nullptr, nullptr}, Excitation{load, nullptr, nullptr}},
                           std::vector<std::string>(b.model->cells.size(), "ELAS"), {});
  ElasticSolve solver2(system2);
  const StaticSolution s2 = solver2.solve(0.0, false);
  EXPECT_LT((s.displacement - s2.displacement).cwiseAbs().maxCoeff(),
            1e-12 * s.displacement.cwiseAbs().maxCoeff());
}

TEST(ElasticSolve, SingularModelNamesTheFreeDof) {
  Bar b = makeBar();
  auto load = std::make_shared<MechanicalLoad>();
  load->model = b.model;
  for (NodeId n : b.left) { // DX blocked, DY free: a vertical rigid translation remains
    load->relations.push_back({{{n, 0, 1.0}}, 0.0, "DDL_IMPO"});
  }
  MechanicalSystem system(b.model, elasticMaterialOn(b.mesh, 1000.0, 0.25),
                          {Excitation{load, nullptr, nullptr}},
                          std::vector<std::string>(b.model->cells.size(), "ELAS"), {});
  ElasticSolve solver(system);
  try {
    solver.solve(0.0, false);
    FAIL() << "a singular system was solved";
  } catch (const UserError& e) {
    const auto& d = e.diagnostics().front();
    EXPECT_EQ(d.id, "SOLVE_1");
    EXPECT_NE(d.message.find("component DY is free"), std::string::npos) << d.message;
    EXPECT_NE(d.message.find("node N"), std::string::npos) << d.message;
  }
}

} // namespace
} // namespace stella
