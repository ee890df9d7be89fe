#pragma once
// A small 3D elastic system for the linear solver tests: HEXA8 cube, clamped face, end load.

#include "solver/behaviour/Elasticity.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "solver/linalg/LinearSolver.hpp"
#include "solver/linalg/Ordering.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace stella::linalg {

// HEXA8 cube of `cells` (4 x 3 x 3 by default) on a 1 x 0.8 x 0.6 box, face x = 0 clamped (by elimination, or
// by Lagrange multipliers), a load in y and z on x = 1.
struct Cube {
  fem::PlainMesh mesh;
  std::vector<std::int64_t> offsets;
  DofNumbering numbering;
  SparseMatrix k;
  Eigen::VectorXd f;

  explicit Cube(bool lagrange, std::array<int, 3> cells = {4, 3, 3})
      : mesh(fem::boxMesh(CellType::HEXA8, cells, {1.0, 0.8, 0.6})), numbering(mesh.nodeCount(), 3) {
    for (int c = 0; c <= mesh.cellCount(); ++c) {
      offsets.push_back(static_cast<std::int64_t>(c) * mesh.nodesPerCell());
    }
    std::vector<std::pair<int, int>> couplings;
    std::vector<int> blocked;
    for (int a = 0; a < mesh.nodeCount(); ++a) {
      for (int c = 0; c < 3 && mesh.coordinates(a, 0) < 1e-12; ++c) {
        if (lagrange) {
          couplings.emplace_back(numbering.addLagrange(Component::LAGR, a, static_cast<Component>(c)),
                                 numbering.dof(a, c));
        } else {
          blocked.push_back(numbering.dof(a, c));
        }
      }
    }
    const CellList cellList{mesh.connectivity, offsets};
    auto pattern = buildPattern(numbering, cellList, couplings, Storage::Upper);
    k = SparseMatrix(pattern);
    const ElementScatter scatter(*pattern, numbering, cellList);
    const Eigen::MatrixXd d = behaviour::elasticMatrix(fem::Modelling::ThreeD, {210000.0, 0.3});
    fem::ElementKinematics kin;
    Eigen::MatrixXd ke, x(8, 3);
    for (int e = 0; e < mesh.cellCount(); ++e) {
      for (int a = 0; a < 8; ++a) {
        x.row(a) = mesh.coordinates.row(mesh.cell(e)[a]);
      }
      fem::computeKinematics(CellType::HEXA8, fem::Modelling::ThreeD, x, kin);
      fem::stiffness(kin, d, ke);
      scatter.add(e, ke, k.values());
    }
    for (const auto& [l, dof] : couplings) {
      k.add(std::min(l, dof), std::max(l, dof), 1.0);
    }
    for (int b : blocked) {
      for (int i = 0; i < pattern->size; ++i) {
        for (auto p = pattern->rowStart[static_cast<std::size_t>(i)];
             p < pattern->rowStart[static_cast<std::size_t>(i) + 1]; ++p) {
          const int j = pattern->columns[static_cast<std::size_t>(p)];
          if (i == b || j == b) {
            k.values()[static_cast<std::size_t>(p)] = i == j ? 1.0 : 0.0;
          }
        }
      }
    }
    f = Eigen::VectorXd::Zero(numbering.dofCount());
    for (int a = 0; a < mesh.nodeCount(); ++a) {
      if (mesh.coordinates(a, 0) > 1.0 - 1e-12) {
        f[numbering.dof(a, 1)] = 100.0;
        f[numbering.dof(a, 2)] = -50.0;
      }
    }
  }
};

} // namespace stella::linalg
