#pragma once
// A small 3D elastic system for the linear solver tests: HEXA8 cube, clamped face, end load;
// numbered and assembled as a run does it (ElasticBox: DofMap, StiffnessMatrix).

#include "solver/linalg/tests/ElasticBox.hpp"

#include <array>

namespace stella::linalg {

// HEXA8 cube of `cells` (4 x 3 x 3 by default) on a 1 x 0.8 x 0.6 box (E = 210000, nu = 0.3), face
// x = 0 clamped (by elimination, or by Lagrange multipliers), a load FY = 100, FZ = -50 on the nodes
// of x = 1.
struct Cube {
  stella::testing::ElasticBox box;
  const SparseMatrix& k;
  Eigen::VectorXd f;

  explicit Cube(bool lagrange, std::array<int, 3> cells = {4, 3, 3})
      : box(fem::boxMesh(CellType::HEXA8, cells, {1.0, 0.8, 0.6}),
            stella::testing::BoxClamp{lagrange ? stella::testing::Clamp::Dualised
                                               : stella::testing::Clamp::Eliminated,
                                      0, 3, 210000.0, 0.3}),
        k(box.matrix), f(Eigen::VectorXd::Zero(box.matrix.size())) {
    for (NodeId a = 0; a < box.mesh->nodeCount(); ++a) {
      if (box.mesh->point(a)[0] > 1.0 - 1e-12) {
        f[box.dofs().dof(a, 1)] = 100.0;
        f[box.dofs().dof(a, 2)] = -50.0;
      }
    }
  }
};

} // namespace stella::linalg
