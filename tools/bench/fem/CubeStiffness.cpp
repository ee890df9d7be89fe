// Assembly of the clamped HEXA8 cube (see CubeStiffness.hpp).

#include "tools/bench/fem/CubeStiffness.hpp"

#include "solver/behaviour/Elasticity.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "tools/bench/fem/PlainAssembly.hpp"

namespace stella::bench {

CubeSystem hexa8Cube(int n) {
  const fem::PlainMesh mesh = fem::boxMesh(CellType::HEXA8, {n, n, n}, {1.0, 1.0, 1.0});
  const fem::Modelling model = fem::Modelling::ThreeD;
  std::vector<std::int64_t> offsets;
  for (int c = 0; c <= mesh.cellCount(); ++c) {
    offsets.push_back(static_cast<std::int64_t>(c) * mesh.nodesPerCell());
  }
  const PlainNumbering numbering{mesh.nodeCount(), 3};
  const CellList cells{mesh.connectivity, offsets};
  const auto pattern = buildPattern(numbering, cells, {}, linalg::Storage::Upper);
  const ElementScatter scatter(*pattern, numbering, cells);
  CubeSystem s{linalg::SparseMatrix(pattern), Eigen::VectorXd::Zero(numbering.dofCount())};
  const Eigen::MatrixXd d = behaviour::elasticMatrix(model, {210000.0, 0.3});
  fem::ElementKinematics kin;
  Eigen::MatrixXd ke, x(mesh.nodesPerCell(), 3);
  for (int e = 0; e < mesh.cellCount(); ++e) {
    for (int a = 0; a < mesh.nodesPerCell(); ++a) {
      x.row(a) = mesh.coordinates.row(mesh.cell(e)[a]);
    }
    fem::computeKinematics(CellType::HEXA8, model, x, kin);
    fem::stiffness(kin, d, ke);
    scatter.add(e, ke, s.k.values());
  }
  std::vector<char> blocked(static_cast<std::size_t>(numbering.dofCount()), 0);
  for (int a = 0; a < mesh.nodeCount(); ++a) {
    for (int c = 0; c < 3; ++c) {
      blocked[static_cast<std::size_t>(numbering.dof(a, c))] = mesh.coordinates(a, 0) < 1e-12 ? 1 : 0;
    }
    if (mesh.coordinates(a, 0) > 1.0 - 1e-12) {
      s.f[numbering.dof(a, 1)] = 1.0;
    }
  }
  for (int i = 0; i < pattern->size; ++i) {
    for (auto p = pattern->rowStart[static_cast<std::size_t>(i)];
         p < pattern->rowStart[static_cast<std::size_t>(i) + 1]; ++p) {
      const int j = pattern->columns[static_cast<std::size_t>(p)];
      if (blocked[static_cast<std::size_t>(i)] != 0 || blocked[static_cast<std::size_t>(j)] != 0) {
        s.k.values()[static_cast<std::size_t>(p)] = i == j ? 1.0 : 0.0;
      }
    }
  }
  return s;
}

} // namespace stella::bench
