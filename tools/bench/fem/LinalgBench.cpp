// Phase timings of a static elastic solve on structured meshes: numbering, sparsity pattern,
// assembly (element stiffness + scatter, load, kinematic constraints), symbolic analysis,
// factorisation, solution and post-processing (stresses at Gauss points), with the peak memory
// after each phase, for MUMPS and CHOLMOD (or UMFPACK) side by side.
//
//   stella-bench-fem CASE DIVISIONS SOLVER [lagrange]
//     CASE      hexa8 | tetra10 | quad4 (plane strain) | quad8
//     DIVISIONS hexahedra (quadrangles) per side of the unit cube (square)
//     SOLVER    MUMPS | MULT_FRONT | GCPC
//     lagrange  dualise the clamped face's DOFs (symmetric indefinite) instead of eliminating them
// Output: one line "key=value ..." per run.
// Numbering, pattern and scatter are the benchmark's own plain-array assembly (PlainAssembly.hpp);
// the run's path (DofMap, StiffnessMatrix, SaddleSolver) is timed by stella-bench-system.

#include "solver/behaviour/Elasticity.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "solver/linalg/LinearSolver.hpp"
#include "solver/loads/SkinLoads.hpp"
#include "solver/nonlinear/PhaseTimes.hpp"
#include "tools/bench/fem/PlainAssembly.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <string>

using namespace stella;

namespace {

struct Clock {
  std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - t).count();
    t = now;
    return s;
  }
};

} // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr
        << "usage: stella-bench-fem hexa8|tetra10|quad4|quad8 DIVISIONS MUMPS|MULT_FRONT|GCPC [lagrange]\n";
    return 2;
  }
  const std::string kase = argv[1];
  const int n = std::stoi(argv[2]);
  const auto method = linalg::solverMethodFromName(argv[3]);
  const bool lagrange = argc > 4 && std::strcmp(argv[4], "lagrange") == 0;
  const std::map<std::string, CellType> types{{"hexa8", CellType::HEXA8},
                                              {"tetra10", CellType::TETRA10},
                                              {"quad4", CellType::QUAD4},
                                              {"quad8", CellType::QUAD8}};
  if (!types.count(kase) || !method) {
    std::cerr << "unknown case or solver\n";
    return 2;
  }
  const CellType type = types.at(kase);
  const bool threeD = dimension(type) == 3;
  const fem::Modelling model = threeD ? fem::Modelling::ThreeD : fem::Modelling::PlaneStrain;
  const int dim = fem::spaceDimension(model);
  std::map<std::string, double> t, mem;

  Clock clock;
  const fem::PlainMesh mesh = fem::boxMesh(type, {n, n, n}, {1.0, 1.0, 1.0});
  std::vector<std::int64_t> offsets;
  for (int c = 0; c <= mesh.cellCount(); ++c) {
    offsets.push_back(static_cast<std::int64_t>(c) * mesh.nodesPerCell());
  }
  t["mesh"] = clock.lap();

  // numbering: clamped face x = 0 (all components), by Lagrange multipliers or elimination
  bench::PlainNumbering numbering{mesh.nodeCount(), dim};
  std::vector<std::pair<int, int>> couplings;
  std::vector<int> blocked;
  for (int a = 0; a < mesh.nodeCount(); ++a) {
    if (mesh.coordinates(a, 0) < 1e-12) {
      for (int c = 0; c < dim; ++c) {
        if (lagrange) {
          couplings.emplace_back(numbering.addMultiplier(), numbering.dof(a, c));
        } else {
          blocked.push_back(numbering.dof(a, c));
        }
      }
    }
  }
  t["numbering"] = clock.lap();
  mem["numbering"] = peakResidentMegabytes();

  const linalg::MatrixKind kind =
      lagrange ? linalg::MatrixKind::SymmetricIndefinite : linalg::MatrixKind::SymmetricPositiveDefinite;
  const bench::CellList cells{mesh.connectivity, offsets};
  const auto pattern = bench::buildPattern(numbering, cells, couplings, linalg::storageFor(kind));
  const bench::ElementScatter scatter(*pattern, numbering, cells);
  linalg::SparseMatrix k(pattern);
  t["pattern"] = clock.lap();
  mem["pattern"] = peakResidentMegabytes();

  // assembly: stiffness, traction on the face x = 1 (nodal lumping through the skin integral is
  // left to the driver; here the load is a uniform nodal force), constraints
  const Eigen::MatrixXd d = behaviour::elasticMatrix(model, {210000.0, 0.3});
  fem::ElementKinematics kin;
  Eigen::MatrixXd ke, x(mesh.nodesPerCell(), dim);
  for (int e = 0; e < mesh.cellCount(); ++e) {
    for (int a = 0; a < mesh.nodesPerCell(); ++a) {
      x.row(a) = mesh.coordinates.row(mesh.cell(e)[a]);
    }
    fem::computeKinematics(type, model, x, kin);
    fem::stiffness(kin, d, ke);
    scatter.add(e, ke, k.values());
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(numbering.dofCount());
  for (int a = 0; a < mesh.nodeCount(); ++a) {
    if (mesh.coordinates(a, 0) > 1.0 - 1e-12) {
      f[numbering.dof(a, 1)] = -1.0;
    }
  }
  for (const auto& [l, dof] : couplings) {
    k.add(std::min(l, dof), std::max(l, dof), 1.0);
  }
  if (!blocked.empty()) { // elimination: zero the rows and columns, unit diagonal
    std::vector<char> isBlocked(static_cast<std::size_t>(numbering.dofCount()), 0);
    for (int b : blocked) {
      isBlocked[static_cast<std::size_t>(b)] = 1;
      f[b] = 0.0;
    }
    for (int i = 0; i < pattern->size; ++i) {
      for (auto p = pattern->rowStart[static_cast<std::size_t>(i)];
           p < pattern->rowStart[static_cast<std::size_t>(i) + 1]; ++p) {
        const int j = pattern->columns[static_cast<std::size_t>(p)];
        if (isBlocked[static_cast<std::size_t>(i)] || isBlocked[static_cast<std::size_t>(j)]) {
          k.values()[static_cast<std::size_t>(p)] = i == j ? 1.0 : 0.0;
        }
      }
    }
  }
  t["assembly"] = clock.lap();
  mem["assembly"] = peakResidentMegabytes();

  linalg::SolverOptions options;
  options.method = *method;
  options.renumbering = "METIS";
  options.relativeResidual = 1e-8;
  auto solver = linalg::makeLinearSolver(options, kind);
  solver->analyse(k);
  t["analyse"] = clock.lap();
  mem["analyse"] = peakResidentMegabytes();
  solver->factorise(k);
  t["factorise"] = clock.lap();
  mem["factorise"] = peakResidentMegabytes();
  Eigen::VectorXd u = f;
  solver->solve(u);
  t["solve"] = clock.lap();
  mem["solve"] = peakResidentMegabytes();
  const double residual = (k.multiply(u) - f).norm() / f.norm();
  clock.lap();

  // post: stresses at every Gauss point
  double maxVm = 0.0;
  Eigen::VectorXd ue(mesh.nodesPerCell() * dim);
  for (int e = 0; e < mesh.cellCount(); ++e) {
    for (int a = 0; a < mesh.nodesPerCell(); ++a) {
      x.row(a) = mesh.coordinates.row(mesh.cell(e)[a]);
      ue.segment(a * dim, dim) = u.segment(numbering.dof(mesh.cell(e)[a], 0), dim);
    }
    fem::computeKinematics(type, model, x, kin);
    for (int q = 0; q < kin.pointCount(); ++q) {
      const Eigen::VectorXd s = d * fem::strainAt(kin, q, ue);
      maxVm = std::max(maxVm, s.cwiseAbs().maxCoeff());
    }
  }
  t["post"] = clock.lap();
  mem["post"] = peakResidentMegabytes();

  const double total =
      t["numbering"] + t["pattern"] + t["assembly"] + t["analyse"] + t["factorise"] + t["solve"] + t["post"];
  const double other = t["numbering"] + t["pattern"] + t["assembly"] + t["post"];
  std::printf("case=%s divisions=%d solver=%s backend=%s lagrange=%d dofs=%d nnz=%lld cells=%d", kase.c_str(),
              n, argv[3], std::string(solver->backendName()).c_str(), lagrange ? 1 : 0, numbering.dofCount(),
              static_cast<long long>(pattern->nonZeros()), mesh.cellCount());
  for (const char* phase :
       {"mesh", "numbering", "pattern", "assembly", "analyse", "factorise", "solve", "post"}) {
    std::printf(" t_%s=%.3f", phase, t[phase]);
  }
  for (const char* phase : {"numbering", "pattern", "assembly", "analyse", "factorise", "solve", "post"}) {
    std::printf(" mem_%s=%.0f", phase, mem[phase]);
  }
  std::printf(" total=%.3f other_share=%.3f residual=%.2e max_stress=%.4g scatter_mb=%.1f\n", total,
              other / total, residual, maxVm, static_cast<double>(scatter.memoryBytes()) / 1048576.0);
  return 0;
}
