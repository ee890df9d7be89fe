// A body held only by discrete springs (DIS_T, notice section 4.4.2) carries a load, the springs
// balancing it; the same body without springs is a singular model whose message names a free
// node and DOF.

#include "solver/fem/BoxMesh.hpp"
#include "solver/nonlinear/LinearStatic.hpp"

#include <gtest/gtest.h>

#include <iostream>

namespace stella::nonlinear {
namespace {

LinearStaticProblem plate(bool springs) {
  const fem::PlainMesh mesh = fem::boxMesh(CellType::QUAD4, {4, 2, 1}, {2.0, 1.0, 1.0});
  LinearStaticProblem pb;
  pb.modelling = fem::Modelling::PlaneStrain;
  pb.material = {1000.0, 0.3};
  pb.coordinates = mesh.coordinates;
  pb.volumes.push_back({CellType::QUAD4, mesh.connectivity});
  PressureLoad load; // pressure 3 on the edge x = 2 (nodes in increasing y: normal +X, outward)
  load.pressure = 3.0;
  load.skin.type = CellType::SEG2;
  std::vector<int> right;
  for (int n = 0; n < mesh.nodeCount(); ++n) {
    if (std::abs(mesh.coordinates(n, 0) - 2.0) < 1e-12) {
      right.push_back(n);
    }
    if (springs) {
      pb.springs.push_back({n, {1.0, 1.0, 0.0}});
    }
  }
  std::sort(right.begin(), right.end(),
            [&](int i, int j) { return mesh.coordinates(i, 1) < mesh.coordinates(j, 1); });
  for (std::size_t i = 0; i + 1 < right.size(); ++i) {
    load.skin.connectivity.push_back(right[i]);
    load.skin.connectivity.push_back(right[i + 1]);
  }
  pb.pressures.push_back(load);
  return pb;
}

TEST(DiscreteSprings, BodyHeldOnlyBySpringsBalancesTheLoad) {
  const LinearStaticProblem pb = plate(true);
  const LinearStaticResult r = solveLinearStatic(pb);
  // the springs carry the resultant -p * L = -3 along X and nothing along Y
  double fx = 0.0, fy = 0.0;
  for (const auto& s : pb.springs) {
    fx -= s.stiffness[0] * r.displacement(s.node, 0);
    fy -= s.stiffness[1] * r.displacement(s.node, 1);
  }
  EXPECT_NEAR(fx, 3.0, 1e-9); // spring forces oppose the applied -3
  EXPECT_NEAR(fy, 0.0, 1e-9);
}

TEST(DiscreteSprings, WithoutSpringsTheModelIsSingularAndTheMessageNamesTheDof) {
  for (auto method : {linalg::SolverMethod::Mumps, linalg::SolverMethod::MultFront}) {
    LinearStaticProblem pb = plate(false);
    pb.solver.method = method;
    try {
      solveLinearStatic(pb);
      ADD_FAILURE() << "a floating body was solved";
    } catch (const linalg::SingularMatrixError& e) {
      // the numbering is rebuilt the same way by the caller; here the equation must be physical
      linalg::DofNumbering numbering(pb.coordinates.rows(), 2);
      ASSERT_GE(e.equation(), 0);
      ASSERT_LT(e.equation(), numbering.physicalDofCount());
      const auto [message, note] = numbering.explainSingularity(e.equation());
      EXPECT_NE(message.find("is free"), std::string::npos);
      std::cout << e.backend() << ": " << message << "\n  " << note << "\n";
    }
  }
}

} // namespace
} // namespace stella::nonlinear
