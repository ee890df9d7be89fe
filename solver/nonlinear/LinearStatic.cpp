// Linear static solve with dualised imposed displacements.

#include "solver/nonlinear/LinearStatic.hpp"

#include "solver/fem/ElementMatrices.hpp"
#include "solver/loads/SkinLoads.hpp"

namespace stella::nonlinear {
namespace {

Eigen::MatrixXd cellCoordinates(const Eigen::MatrixXd& coords, const int* nodes, int n) {
  Eigen::MatrixXd x(n, coords.cols());
  for (int a = 0; a < n; ++a) {
    x.row(a) = coords.row(nodes[a]);
  }
  return x;
}

} // namespace

LinearStaticResult solveLinearStatic(const LinearStaticProblem& pb) {
  const int dim = fem::spaceDimension(pb.modelling);
  const int nodes = static_cast<int>(pb.coordinates.rows());
  // nodes carried by volume cells get DOFs
  auto active = std::make_unique<bool[]>(static_cast<std::size_t>(nodes)); // value-initialised: false
  std::vector<int> connectivity;
  std::vector<std::int64_t> offsets{0};
  for (const CellBlock& b : pb.volumes) {
    for (int node : b.connectivity) {
      active[static_cast<std::size_t>(node)] = true;
    }
    for (int c = 0; c < b.cellCount(); ++c) {
      const int n = nodeCount(b.type);
      connectivity.insert(connectivity.end(), b.connectivity.begin() + c * n,
                          b.connectivity.begin() + (c + 1) * n);
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
  }
  for (const NodalSpring& sp : pb.springs) {
    active[static_cast<std::size_t>(sp.node)] = true;
  }
  auto numbering = std::make_shared<linalg::DofNumbering>(
      nodes, dim, std::span<const bool>(active.get(), static_cast<std::size_t>(nodes)));
  std::vector<std::pair<int, int>> couplings;
  for (const ImposedDisplacement& d : pb.imposed) {
    const int dof = numbering->dof(d.node, d.component);
    couplings.emplace_back(
        numbering->addLagrange(linalg::Component::LAGR, d.node, static_cast<linalg::Component>(d.component)),
        dof);
  }
  const linalg::MatrixKind kind = couplings.empty() ? linalg::MatrixKind::SymmetricPositiveDefinite
                                                    : linalg::MatrixKind::SymmetricIndefinite;
  const linalg::CellList cells{connectivity, offsets};
  const auto pattern = linalg::buildPattern(*numbering, cells, couplings, linalg::storageFor(kind));
  const linalg::ElementScatter scatter(*pattern, *numbering, cells);
  linalg::SparseMatrix k(pattern);
  const Eigen::MatrixXd d = behaviour::elasticMatrix(pb.modelling, pb.material);
  fem::ElementKinematics kin;
  Eigen::MatrixXd ke;
  int cell = 0;
  for (const CellBlock& b : pb.volumes) {
    const int n = nodeCount(b.type);
    for (int c = 0; c < b.cellCount(); ++c, ++cell) {
      fem::computeKinematics(b.type, pb.modelling,
                             cellCoordinates(pb.coordinates, b.connectivity.data() + c * n, n), kin,
                             pb.volumeStrain);
      fem::stiffness(kin, d, ke);
      scatter.add(cell, ke, k.values());
    }
  }
  for (const NodalSpring& sp : pb.springs) { // diagonal entries are always in the pattern
    for (int c = 0; c < dim; ++c) {
      const int dof = numbering->dof(sp.node, c);
      k.add(dof, dof, sp.stiffness[static_cast<std::size_t>(c)]);
    }
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(numbering->dofCount());
  if (pb.nodalForces.size() > 0) {
    for (int a = 0; a < nodes; ++a) {
      if (numbering->firstDof(a) >= 0) {
        f.segment(numbering->firstDof(a), dim) += pb.nodalForces.segment(a * dim, dim);
      }
    }
  }
  for (const PressureLoad& p : pb.pressures) {
    const int n = nodeCount(p.skin.type);
    for (int c = 0; c < p.skin.cellCount(); ++c) {
      const int* sn = p.skin.connectivity.data() + c * n;
      const Eigen::VectorXd fe =
          loads::pressureForces(p.skin.type, pb.modelling, cellCoordinates(pb.coordinates, sn, n),
                                Eigen::VectorXd::Constant(n, p.pressure));
      for (int a = 0; a < n; ++a) {
        f.segment(numbering->firstDof(sn[a]), dim) += fe.segment(a * dim, dim);
      }
    }
  }
  // K_phys only, for reactions; then the multiplier couplings and their right-hand sides
  const linalg::SparseMatrix stiffnessOnly = k;
  for (std::size_t i = 0; i < couplings.size(); ++i) {
    const auto [l, dof] = couplings[i];
    k.add(std::min(l, dof), std::max(l, dof), 1.0);
    f[l] = pb.imposed[i].value;
  }
  auto solver = linalg::makeLinearSolver(pb.solver, kind);
  solver->analyse(k);
  solver->factorise(k);
  LinearStaticResult r;
  r.numbering = numbering;
  r.solution = f;
  solver->solve(r.solution);
  Eigen::VectorXd physical = r.solution;
  physical.tail(numbering->dofCount() - numbering->physicalDofCount()).setZero();
  Eigen::VectorXd fPhysical = f;
  fPhysical.tail(numbering->dofCount() - numbering->physicalDofCount()).setZero();
  const Eigen::VectorXd reaction = stiffnessOnly.multiply(physical) - fPhysical;
  r.displacement = Eigen::MatrixXd::Zero(nodes, dim);
  r.reactions = Eigen::MatrixXd::Zero(nodes, dim);
  for (int a = 0; a < nodes; ++a) {
    if (numbering->firstDof(a) >= 0) {
      r.displacement.row(a) = r.solution.segment(numbering->firstDof(a), dim).transpose();
      r.reactions.row(a) = reaction.segment(numbering->firstDof(a), dim).transpose();
    }
  }
  return r;
}

} // namespace stella::nonlinear
