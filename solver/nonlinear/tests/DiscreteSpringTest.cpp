// A body held only by discrete springs (2D_DIS_T on POI1 cells, AFFE_CARA_ELEM K_T_D_N, notice
// section 4.4.2) carries a pressure, the springs balancing it; the same body without springs is a
// singular model whose message (SOLVE_1) names a free node and DOF and advises the springs.
// Solved as MECA_STATIQUE does: MechanicalSystem (DofMap, VolumeAssembler) and ElasticSolve.

#include "interpreter/Diagnostics.hpp"
#include "solver/assembly/tests/ElasticStudy.hpp"
#include "solver/nonlinear/ElasticSolve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace stella {
namespace {

struct Plate {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::shared_ptr<MechanicalLoad> load;
  std::shared_ptr<ElementCharacteristics> springs; // null: none
};

// QUAD4 plate 2 x 1 (4 x 2 cells, D_PLAN, E = 1000, nu = 0.3), pressure 3 on the edge x = 2 (SEG2
// cells in increasing y: the force -3 along X), with a spring (1, 1) on every node when `held`.
Plate plate(bool held) {
  Plate p;
  p.mesh = fem::toMesh(fem::boxMesh(CellType::QUAD4, {4, 2, 1}, {2.0, 1.0, 1.0}));
  const NodeId nodes = p.mesh->nodeCount();
  std::vector<CellId> volumes = testing::allCells(*p.mesh);
  std::vector<std::pair<double, NodeId>> right;
  for (NodeId n = 0; n < nodes; ++n) {
    if (std::abs(p.mesh->point(n)[0] - 2.0) < 1e-12) {
      right.emplace_back(p.mesh->point(n)[1], n);
    }
  }
  std::sort(right.begin(), right.end());
  std::vector<CellId> edges;
  for (std::size_t i = 0; i + 1 < right.size(); ++i) {
    const NodeId edge[2] = {right[i].second, right[i + 1].second};
    edges.push_back(p.mesh->addCell(CellType::SEG2, edge));
  }
  std::vector<CellId> points;
  for (NodeId n = 0; held && n < nodes; ++n) {
    const NodeId one[] = {n};
    points.push_back(p.mesh->addCell(CellType::POI1, one));
  }
  p.model = std::make_shared<Model>(p.mesh);
  volumes.insert(volumes.end(), edges.begin(), edges.end());
  assignModelling(*p.model, volumes, "D_PLAN", {});
  if (held) {
    assignModelling(*p.model, points, "2D_DIS_T", {});
  }
  finishModel(*p.model, {});
  p.load = std::make_shared<MechanicalLoad>();
  p.load->model = p.model;
  for (CellId c : edges) {
    p.load->pressures.push_back({c, 3.0});
  }
  if (held) {
    p.springs = std::make_shared<ElementCharacteristics>();
    p.springs->model = p.model;
    for (NodeId n = 0; n < nodes; ++n) {
      p.springs->springs.push_back({points[static_cast<std::size_t>(n)], n, {1.0, 1.0, 0.0}});
    }
  }
  return p;
}

TEST(DiscreteSprings, BodyHeldOnlyBySpringsBalancesTheLoad) {
  const Plate p = plate(true);
  MechanicalSystem system(p.model, testing::elasticMaterialOn(p.mesh, 1000.0, 0.3),
                          {Excitation{p.load, nullptr, nullptr}}, testing::elasticEverywhere(*p.model), {},
                          p.springs);
  const StaticSolution s = ElasticSolve(system).solve(0.0, false);
  // the springs carry the resultant -p * L = -3 along X and nothing along Y
  double fx = 0.0;
  double fy = 0.0;
  for (const auto& sp : p.springs->springs) {
    fx -= sp.stiffness[0] * s.displacement(system.dofs().dof(sp.node, 0));
    fy -= sp.stiffness[1] * s.displacement(system.dofs().dof(sp.node, 1));
  }
  EXPECT_NEAR(fx, 3.0, 1e-9); // spring forces oppose the applied -3
  EXPECT_NEAR(fy, 0.0, 1e-9);
}

TEST(DiscreteSprings, WithoutSpringsTheModelIsSingularAndTheMessageNamesTheDof) {
  for (auto method : {linalg::SolverMethod::Mumps, linalg::SolverMethod::MultFront}) {
    const Plate p = plate(false);
    MechanicalSystem system(p.model, testing::elasticMaterialOn(p.mesh, 1000.0, 0.3),
                            {Excitation{p.load, nullptr, nullptr}}, testing::elasticEverywhere(*p.model), {});
    linalg::SolverOptions o;
    o.method = method;
    system.solver().setOptions(o);
    try {
      ElasticSolve(system).solve(0.0, false);
      ADD_FAILURE() << "a floating body was solved";
    } catch (const UserError& e) {
      const Diagnostic& d = e.diagnostics().front();
      EXPECT_EQ(d.id, "SOLVE_1");
      EXPECT_NE(d.message.find("is free"), std::string::npos) << d.message;
      EXPECT_NE(d.message.find("node N"), std::string::npos) << d.message;
      ASSERT_FALSE(d.notes.empty());
      EXPECT_NE(d.notes.front().find("DIS_T"), std::string::npos) << d.notes.front();
      std::cout << d.message << "\n  " << d.notes.front() << "\n";
    }
  }
}

} // namespace
} // namespace stella
