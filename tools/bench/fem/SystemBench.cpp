// Phase timings of MECA_STATIQUE's path without the command layer: Mesh -> Model -> MechanicalSystem
// (DOF numbering, behaviours, constraint rows, matrix pattern) -> VolumeAssembler (element
// stiffness added in place) -> SaddleSolver (bordered matrix, analysis, factorisation) ->
// solve -> post (stresses at every Gauss point), with the peak memory after each phase.
// The clamped face x = 0 is eliminated (AFFE_CHAR_CINE: SPD, CHOLMOD for MULT_FRONT) or dualised
// (`lagrange`: DDL_IMPO, symmetric indefinite); unit nodal forces on the face x = 1.
//
//   stella-bench-system CASE DIVISIONS SOLVER [lagrange] [dualised] [old]
//     CASE      hexa8 | tetra10 | quad4 (plane strain) | quad8
//     DIVISIONS hexahedra (quadrangles) per side of the unit cube (square)
//     SOLVER    MUMPS | MULT_FRONT
//     dualised  with `lagrange`: every DDL_IMPO keeps its multiplier (the path before the
//               SaddleSolver eliminated single-DOF relations: symmetric indefinite)
//     old       the former path: triplets and the singularity diagnosis before the factorisation
//               (default: the in-place assembly into the StiffnessMatrix pattern, MECA_STATIQUE's)
// Output: one line "key=value ..." per run.

#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/model/ModelBuilder.hpp"
#include "solver/nonlinear/PhaseTimes.hpp"
#include "solver/nonlinear/PointState.hpp"

#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
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
                 "[dualised] [old]\n";
    return 2;
  }
  const std::string kase = argv[1];
  const int n = std::atoi(argv[2]);
  const std::string solverName = argv[3];
  bool lagrange = false;
  bool oldPath = false;
  bool dualised = false;
  for (int i = 4; i < argc; ++i) {
    dualised = dualised || std::strcmp(argv[i], "dualised") == 0;
    lagrange = lagrange || std::strcmp(argv[i], "lagrange") == 0;
    oldPath = oldPath || std::strcmp(argv[i], "old") == 0;
  }
  const CellType type = kase == "hexa8"     ? CellType::HEXA8
                        : kase == "tetra10" ? CellType::TETRA10
                        : kase == "quad8"   ? CellType::QUAD8
                                            : CellType::QUAD4;
  const bool threeD = dimension(type) == 3;
  Clock clock;
  auto mesh = fem::toMesh(fem::boxMesh(type, {n, n, threeD ? n : 1}, {1.0, 1.0, 1.0}));
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
  const double mMesh = peakResidentMegabytes();

  std::vector<Excitation> ex{{load, nullptr, nullptr}};
  if (!lagrange) {
    ex.push_back({nullptr, kinematic, nullptr});
  }
  MechanicalSystem system(model, steel(mesh), ex, std::vector<std::string>(model->cells.size(), "ELAS"), {});
  linalg::SolverOptions options;
  options.method = solverName == "MULT_FRONT" ? linalg::SolverMethod::MultFront : linalg::SolverMethod::Mumps;
  system.solver().setOptions(options);
  system.solver().condenseSingleDofRelations(!dualised);
  const double tNumbering = clock.lap();
  const double mNumbering = peakResidentMegabytes();

  const int np = system.dofs().physicalCount();
  const PointState zero = zeroPointState(system.model(), system.behaviours().maxInternalVariables());
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(np);
  double tPattern = 0.0;
  std::int64_t nnz = 0;
  std::size_t matrixBytes = 0;
  Eigen::VectorXd f;
  Eigen::VectorXd g;
  Eigen::VectorXd p;
  double tElements = 0.0;
  double tAssembly = 0.0;
  double tFactorise = 0.0;
  double mAssembly = 0.0;
  if (oldPath) {
    // The former path: element matrices as triplets, then the compressed matrix; the singularity
    // diagnosis factorised first (what MECA_STATIQUE did before the in-place assembly).
    std::vector<Eigen::Triplet<double>> triplets;
    system.assembler().run(none, none, zero, behaviour::Option::ElasticTangent,
                           {&triplets, nullptr, nullptr});
    tElements = clock.lap();
    const Eigen::SparseMatrix<double> k = system.matrix(triplets);
    std::vector<Eigen::Triplet<double>>().swap(triplets);
    nnz = k.nonZeros();
    f = system.externalForces(0.0);
    g = system.relationValues(0.0);
    p = system.eliminatedValues(0.0);
    tAssembly = tElements + clock.lap();
    mAssembly = peakResidentMegabytes();
    system.solver().factorize(k, true, true);
    tFactorise = clock.lap();
  } else {
    StiffnessMatrix& k = system.stiffness(true);
    tPattern = clock.lap();
    system.assembler().run(none, none, zero, behaviour::Option::ElasticTangent,
                           {nullptr, nullptr, nullptr, &k});
    tElements = clock.lap();
    nnz = k.toEigen().nonZeros();
    matrixBytes = k.memoryBytes();
    clock.lap();
    f = system.externalForces(0.0);
    g = system.relationValues(0.0);
    p = system.eliminatedValues(0.0);
    tAssembly = tElements + clock.lap();
    mAssembly = peakResidentMegabytes();
    system.solver().factorize(k, true);
    tFactorise = clock.lap();
  }
  const double tNumberingAll = tNumbering + tPattern;
  const double mFactorise = peakResidentMegabytes();

  Eigen::VectorXd u;
  Eigen::VectorXd lambda;
  system.solver().solve(f, g, p, u, lambda);
  const double tSolve = clock.lap();
  const double mSolve = peakResidentMegabytes();

  PointState state = zero;
  system.assembler().run(none, u, zero, behaviour::Option::Full, {nullptr, nullptr, &state});
  const double tPost = clock.lap();
  const double mPost = peakResidentMegabytes();

  const double total = tNumberingAll + tAssembly + tFactorise + tSolve + tPost;
  const double other = tNumberingAll + tAssembly + tPost;
  std::cout << "case=" << kase << " divisions=" << n << " solver=" << solverName
            << " backend=" << system.solver().backendName() << " lagrange=" << (lagrange ? 1 : 0)
            << " dualised=" << (dualised ? 1 : 0)
            << " multipliers=" << system.solver().borderedRelationCount()
            << " path=" << (oldPath ? "old" : "new") << " dofs=" << system.dofs().size()
            << " cells=" << mesh->cellCount() << " nnz=" << nnz << " matrix_mb=" << matrixBytes / 1048576.0
            << " t_mesh=" << tMesh << " t_numbering=" << tNumberingAll << " t_pattern=" << tPattern
            << " t_assembly=" << tAssembly << " t_elements=" << tElements << " t_factorise=" << tFactorise
            << " t_solve=" << tSolve << " t_post=" << tPost << " mem_mesh=" << mMesh
            << " mem_numbering=" << mNumbering << " mem_assembly=" << mAssembly
            << " mem_factorise=" << mFactorise << " mem_solve=" << mSolve << " mem_post=" << mPost
            << " total=" << total << " other_share=" << other / total << " max_u=" << u.cwiseAbs().maxCoeff()
            << "\n";
  return 0;
}
