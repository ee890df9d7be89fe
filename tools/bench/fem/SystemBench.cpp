// Phase timings of MECA_STATIQUE's real path (what a .comm runs): Mesh -> Model -> MechanicalSystem
// (DOF numbering, behaviours, constraint rows) -> VolumeAssembler (element stiffness as matrix
// triplets, then the compressed matrix) -> SaddleSolver (singularity check + factorisation) ->
// solve -> post (stresses at every Gauss point), with the peak memory after each phase.
// The clamped face x = 0 is eliminated (AFFE_CHAR_CINE: SPD, CHOLMOD for MULT_FRONT) or dualised
// (`lagrange`: DDL_IMPO, symmetric indefinite); unit nodal forces on the face x = 1.
//
//   stella-bench-system CASE DIVISIONS SOLVER [lagrange] [nocheck]
//     CASE      hexa8 | tetra10 | quad4 (plane strain) | quad8
//     DIVISIONS hexahedra (quadrangles) per side of the unit cube (square)
//     SOLVER    MUMPS | MULT_FRONT
//     nocheck   factorise without the singularity pre-check (to measure what it costs)
// Output: one line "key=value ..." per run.

#include "solver/fem/BoxMesh.hpp"
#include "solver/model/ModelBuilder.hpp"
#include "solver/nonlinear/MechanicalSystem.hpp"
#include "solver/nonlinear/PointState.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

using namespace stella;

namespace {

double peakMegabytes() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line)) {
    if (line.rfind("VmHWM:", 0) == 0) {
      return std::stod(line.substr(6)) / 1024.0;
    }
  }
  return 0.0;
}

struct Clock {
  std::chrono::steady_clock::time_point t = std::chrono::steady_clock::now();
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - t).count();
    t = now;
    return s;
  }
};

std::shared_ptr<Mesh> toMesh(const fem::PlainMesh& p) {
  auto mesh = std::make_shared<Mesh>();
  mesh->setDimension(p.dimension);
  for (int n = 0; n < p.nodeCount(); ++n) {
    Point3 x{0, 0, 0};
    for (int d = 0; d < p.dimension; ++d) {
      x[static_cast<std::size_t>(d)] = p.coordinates(n, d);
    }
    mesh->addNode(x);
  }
  for (int c = 0; c < p.cellCount(); ++c) {
    mesh->addCell(p.cellType, std::span<const NodeId>(p.cell(c), static_cast<std::size_t>(p.nodesPerCell())));
  }
  return mesh;
}

std::shared_ptr<MaterialField> steel(std::shared_ptr<const Mesh> mesh) {
  auto m = std::make_shared<Material>();
  m->name = "STEEL";
  m->elastic = ElasticMaterial{210000.0, 0.3, {}, {}};
  auto f = std::make_shared<MaterialField>();
  f->mesh = mesh;
  f->materials.push_back(m);
  f->cellMaterial.assign(static_cast<std::size_t>(mesh->cellCount()), 0);
  return f;
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: stella-bench-system hexa8|tetra10|quad4|quad8 DIVISIONS MUMPS|MULT_FRONT [lagrange] "
                 "[nocheck]\n";
    return 2;
  }
  const std::string kase = argv[1];
  const int n = std::atoi(argv[2]);
  const std::string solverName = argv[3];
  bool lagrange = false;
  bool check = true;
  for (int i = 4; i < argc; ++i) {
    lagrange = lagrange || std::strcmp(argv[i], "lagrange") == 0;
    check = check && std::strcmp(argv[i], "nocheck") != 0;
  }
  const CellType type = kase == "hexa8"     ? CellType::HEXA8
                        : kase == "tetra10" ? CellType::TETRA10
                        : kase == "quad8"   ? CellType::QUAD8
                                            : CellType::QUAD4;
  const bool threeD = dimension(type) == 3;
  Clock clock;
  auto mesh = toMesh(fem::boxMesh(type, {n, n, threeD ? n : 1}, {1.0, 1.0, 1.0}));
  auto model = std::make_shared<Model>(mesh);
  std::vector<CellId> all(static_cast<std::size_t>(mesh->cellCount()));
  for (CellId c = 0; c < mesh->cellCount(); ++c) {
    all[static_cast<std::size_t>(c)] = c;
  }
  assignModelling(*model, all, threeD ? "3D" : "D_PLAN", {});
  finishModel(*model, {});
  const int dim = model->components;
  auto load = std::make_shared<MechanicalLoad>();
  load->model = model;
  auto kinematic = std::make_shared<KinematicLoad>();
  kinematic->model = model;
  for (NodeId node = 0; node < mesh->nodeCount(); ++node) {
    const Point3 x = mesh->point(node);
    if (x[0] < 1e-12) {
      for (int c = 0; c < dim; ++c) {
        if (lagrange) {
          load->relations.push_back({{{node, c, 1.0}}, 0.0, "DDL_IMPO"});
        } else {
          kinematic->imposed.push_back({node, c, 0.0});
        }
      }
    } else if (x[0] > 1.0 - 1e-12) {
      load->nodalForces.push_back({node, 1, 1.0});
    }
  }
  const double tMesh = clock.lap();
  const double mMesh = peakMegabytes();

  std::vector<Excitation> ex{{load, nullptr, nullptr}};
  if (!lagrange) {
    ex.push_back({nullptr, kinematic, nullptr});
  }
  MechanicalSystem system(model, steel(mesh), ex, std::vector<std::string>(model->cells.size(), "ELAS"), {});
  linalg::SolverOptions options;
  options.method = solverName == "MULT_FRONT" ? linalg::SolverMethod::MultFront : linalg::SolverMethod::Mumps;
  system.solver().setOptions(options);
  const double tNumbering = clock.lap();
  const double mNumbering = peakMegabytes();

  const int np = system.dofs().physicalCount();
  const PointState zero = zeroPointState(system.model(), system.behaviours().maxInternalVariables());
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(np);
  std::vector<Eigen::Triplet<double>> triplets;
  system.assembler().run(none, none, zero, behaviour::Option::ElasticTangent, {&triplets, nullptr, nullptr});
  const double tElements = clock.lap();
  const std::size_t tripletCount = triplets.size();
  const Eigen::SparseMatrix<double> k = system.matrix(triplets);
  std::vector<Eigen::Triplet<double>>().swap(triplets);
  const Eigen::VectorXd f = system.externalForces(0.0);
  const Eigen::VectorXd g = system.relationValues(0.0);
  const Eigen::VectorXd p = system.eliminatedValues(0.0);
  const double tAssembly = tElements + clock.lap();
  const double mAssembly = peakMegabytes();

  system.solver().factorize(k, check, true);
  const double tFactorise = clock.lap();
  const double mFactorise = peakMegabytes();

  Eigen::VectorXd u;
  Eigen::VectorXd lambda;
  system.solver().solve(f, g, p, u, lambda);
  const double tSolve = clock.lap();
  const double mSolve = peakMegabytes();

  PointState state = zero;
  system.assembler().run(none, u, zero, behaviour::Option::Full, {nullptr, nullptr, &state});
  const double tPost = clock.lap();
  const double mPost = peakMegabytes();

  const double total = tNumbering + tAssembly + tFactorise + tSolve + tPost;
  const double other = tNumbering + tAssembly + tPost;
  std::cout << "case=" << kase << " divisions=" << n << " solver=" << solverName
            << " backend=" << system.solver().backendName() << " lagrange=" << (lagrange ? 1 : 0)
            << " check=" << (check ? 1 : 0) << " dofs=" << system.dofs().size()
            << " cells=" << mesh->cellCount() << " triplets=" << tripletCount << " nnz=" << k.nonZeros()
            << " t_mesh=" << tMesh << " t_numbering=" << tNumbering << " t_assembly=" << tAssembly
            << " t_elements=" << tElements << " t_factorise=" << tFactorise << " t_solve=" << tSolve
            << " t_post=" << tPost << " mem_mesh=" << mMesh << " mem_numbering=" << mNumbering
            << " mem_assembly=" << mAssembly << " mem_factorise=" << mFactorise << " mem_solve=" << mSolve
            << " mem_post=" << mPost << " total=" << total << " other_share=" << other / total
            << " max_u=" << u.cwiseAbs().maxCoeff() << "\n";
  return 0;
}
