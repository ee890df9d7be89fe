// The in-place assembly of K (StiffnessMatrix) against the triplet assembly, entry for entry; the
// growing extra pattern of couplings outside the cells and the re-analysis it triggers in the
// SaddleSolver; singular stiffness found by the backends (no pre-check) and still named; an
// iterative solve that does not converge is the user's SOLVE_2, not an internal error.

#include "interpreter/Diagnostics.hpp"
#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/assembly/tests/ElasticStudy.hpp"
#include "solver/model/ModelBuilder.hpp"
#include "solver/nonlinear/ElasticSolve.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseLU>

namespace stella {
namespace {

std::shared_ptr<Mesh> boxOf(CellType type, int n) {
  const bool threeD = dimension(type) == 3;
  return fem::toMesh(fem::boxMesh(type, {n, n + 1, threeD ? n : 1}, {1.0, 1.2, 0.8}));
}

struct Study {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::unique_ptr<MechanicalSystem> system;
};

// Clamped on x = 0 (eliminated or dualised), FY = 1 on the nodes of x = 1; `hold` false leaves
// DY free on x = 0 (a rigid vertical translation: singular).
Study study(CellType type, int n, bool eliminate, bool hold = true) {
  Study s;
  s.mesh = boxOf(type, n);
  s.model = std::make_shared<Model>(s.mesh);
  std::vector<CellId> all;
  for (CellId c = 0; c < s.mesh->cellCount(); ++c) {
    all.push_back(c);
  }
  const bool threeD = dimension(type) == 3;
  assignModelling(*s.model, all, threeD ? "3D" : "D_PLAN", {});
  finishModel(*s.model, {});
  auto load = std::make_shared<MechanicalLoad>();
  load->model = s.model;
  auto kin = std::make_shared<KinematicLoad>();
  kin->model = s.model;
  for (NodeId node = 0; node < s.mesh->nodeCount(); ++node) {
    const Point3 x = s.mesh->point(node);
    if (x[0] < 1e-12) {
      for (int c = 0; c < s.model->components; ++c) {
        if (!hold && c == 1) {
          continue;
        }
        if (eliminate) {
          kin->imposed.push_back({node, c, c == 0 ? 1e-4 : 0.0});
        } else {
          load->relations.push_back({{{node, c, 1.0}}, c == 0 ? 1e-4 : 0.0, "DDL_IMPO"});
        }
      }
    } else if (x[0] > 1.0 - 1e-12) {
      load->nodalForces.push_back({node, 1, 1.0});
    }
  }
  auto field = testing::elasticMaterialOn(s.mesh, 210000.0, 0.3);
  std::vector<Excitation> ex{{load, nullptr, nullptr}};
  if (eliminate) {
    ex.push_back({nullptr, kin, nullptr});
  }
  s.system = std::make_unique<MechanicalSystem>(
      s.model, field, ex, std::vector<std::string>(s.model->cells.size(), "ELAS"), SourceLocation{});
  return s;
}

Eigen::SparseMatrix<double> viaTriplets(MechanicalSystem& system) {
  const int n = system.dofs().physicalCount();
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(n);
  const PointState zero = zeroPointState(system.model(), system.behaviours().maxInternalVariables());
  std::vector<Eigen::Triplet<double>> t;
  system.assembler().run(none, none, zero, behaviour::Option::ElasticTangent, {&t, nullptr, nullptr});
  return system.matrix(t);
}

StiffnessMatrix& inPlace(MechanicalSystem& system, bool symmetric) {
  const int n = system.dofs().physicalCount();
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(n);
  const PointState zero = zeroPointState(system.model(), system.behaviours().maxInternalVariables());
  StiffnessMatrix& k = system.stiffness(symmetric);
  system.assembler().run(none, none, zero, behaviour::Option::ElasticTangent,
                         {nullptr, nullptr, nullptr, &k});
  return k;
}

// Same sums in the same cell order: the entries must be identical, not only close. Upper storage
// keeps the upper triangle (the element matrices are symmetric only to round-off).
void expectIdentical(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b, bool upper) {
  ASSERT_EQ(a.rows(), b.rows());
  Eigen::MatrixXd da(a);
  Eigen::MatrixXd db(b);
  if (upper) {
    da = da.triangularView<Eigen::Upper>();
    db = db.triangularView<Eigen::Upper>();
  }
  EXPECT_EQ((da - db).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(da.cwiseAbs().maxCoeff(), 0.0);
}

TEST(StiffnessMatrix, InPlaceAssemblyEqualsTheTripletsExactly) {
  for (CellType type : {CellType::HEXA8, CellType::TETRA10, CellType::QUAD4, CellType::QUAD8}) {
    Study s = study(type, 2, true);
    const Eigen::SparseMatrix<double> reference = viaTriplets(*s.system);
    expectIdentical(inPlace(*s.system, true).toEigen(), reference, true);
    expectIdentical(inPlace(*s.system, false).toEigen(), reference, false);
  }
}

TEST(StiffnessMatrix, EntriesOutsideTheCellsGrowAnExtraPatternOnce) {
  Study s = study(CellType::QUAD4, 3, true);
  StiffnessMatrix& k = inPlace(*s.system, true);
  const Eigen::MatrixXd before(k.toEigen());
  const auto id = k.patternId();
  const int last = k.size() - 1;
  k.add({{0, last, 5.0}, {last, 0, 5.0}, {1, 1, 2.0}}); // (0, last): no cell holds both
  EXPECT_NE(k.patternId(), id);
  const auto grown = k.patternId();
  k.add({{0, last, 1.0}});
  EXPECT_EQ(k.patternId(), grown); // already in the extra pattern
  const Eigen::MatrixXd after(k.toEigen());
  EXPECT_EQ(after(0, last), 6.0);
  EXPECT_EQ(after(last, 0), 6.0);
  EXPECT_EQ(after(1, 1), before(1, 1) + 2.0);
  k.setZero();
  EXPECT_EQ(k.patternId(), grown); // zeroing keeps the pattern
  EXPECT_EQ(k.toEigen().coeff(0, last), 0.0);
}

TEST(StiffnessMatrix, SaddleSolverAnalysesOnlyWhenThePatternGrows) {
  for (const char* method : {"MUMPS", "MULT_FRONT"}) {
    for (bool eliminate : {true, false}) {
      Study s = study(CellType::QUAD4, 4, eliminate);
      linalg::SolverOptions o;
      o.method = *linalg::solverMethodFromName(method);
      MechanicalSystem& system = *s.system;
      system.solver().setOptions(o);
      system.solver().keepFactorsOfUnchangedMatrix(true);
      const Eigen::VectorXd f = system.externalForces(0.0);
      const Eigen::VectorXd g = system.relationValues(0.0);
      const Eigen::VectorXd p = system.eliminatedValues(0.0);
      Eigen::VectorXd u;
      Eigen::VectorXd lambda;
      system.solver().factorize(inPlace(system, true));
      system.solver().solve(f, g, p, u, lambda);
      // the former path: K from triplets, given as an Eigen matrix
      Eigen::VectorXd u0;
      Eigen::VectorXd lambda0;
      SaddleSolver reference(system.dofs(), *s.mesh, {}, system.solver().eliminated());
      if (eliminate) {
        reference.setOptions(o);
        reference.factorize(viaTriplets(system), true);
        reference.solve(f, g, p, u0, lambda0);
        EXPECT_LE((u - u0).cwiseAbs().maxCoeff(), 1e-12 * u0.cwiseAbs().maxCoeff()) << method;
        // by default (a single solve, MECA_STATIQUE) no copy is kept and the same matrix is
        // factorised again
        reference.factorize(viaTriplets(system), false);
        EXPECT_EQ(reference.factorizations(), 2) << method;
        EXPECT_EQ(reference.reusedFactorizations(), 0) << method;
      }
      EXPECT_EQ(system.solver().timings().analyses, 1);
      system.solver().factorize(inPlace(system, true));
      EXPECT_EQ(system.solver().timings().analyses, 1) << method;
      // the same values again (an elastic tangent): the factors are kept, the solution is the same
      EXPECT_EQ(system.solver().factorizations(), 1) << method;
      EXPECT_EQ(system.solver().reusedFactorizations(), 1) << method;
      Eigen::VectorXd uAgain;
      Eigen::VectorXd lambdaAgain;
      system.solver().solve(f, g, p, uAgain, lambdaAgain);
      EXPECT_EQ((uAgain - u).cwiseAbs().maxCoeff(), 0.0) << method;
      // a penalty spring between two far nodes (a contact pair): new pattern, new analysis
      StiffnessMatrix& k = inPlace(system, true);
      const int a = system.dofs().physicalCount() - 1;
      const int b = system.dofs().dof(1, 1); // a node of y = 0 next to x = 0, free
      const double c = 1.0e5;
      k.add({{a, b, -c}, {b, a, -c}, {a, a, c}, {b, b, c}});
      system.solver().factorize(k);
      EXPECT_EQ(system.solver().timings().analyses, 2) << method;
      EXPECT_EQ(system.solver().factorizations(), 2) << method;
      Eigen::VectorXd u2;
      Eigen::VectorXd lambda2;
      system.solver().solve(f, g, p, u2, lambda2);
      // residual of the full system K u + C^T lambda = f, C u = g (eliminated DOFs prescribed)
      const Eigen::SparseMatrix<double> kk = k.toEigen();
      Eigen::VectorXd r = kk * u2 + system.solver().transposeTimes(lambda2) - f;
      for (int i = 0; i < r.size(); ++i) {
        if (system.solver().eliminated()[static_cast<std::size_t>(i)]) {
          r(i) = u2(i) - p(i);
        }
      }
      EXPECT_LE(r.cwiseAbs().maxCoeff(), 1e-8 * f.cwiseAbs().maxCoeff()) << method << " " << eliminate;
      if (g.size() > 0) {
        EXPECT_LE((system.solver().times(u2) - g).cwiseAbs().maxCoeff(), 1e-12);
      }
    }
  }
}

TEST(StiffnessMatrix, SingularStiffnessIsFoundByTheBackendAndNamed) {
  // No pre-check any more: MUMPS (null pivots), CHOLMOD (not positive definite) and UMFPACK find
  // the singularity during the factorisation, then the diagnosis names the free DOF.
  for (const char* method : {"MUMPS", "MULT_FRONT"}) {
    for (bool eliminate : {true, false}) {
      Study s = study(CellType::QUAD4, 3, eliminate, false);
      linalg::SolverOptions o;
      o.method = *linalg::solverMethodFromName(method);
      s.system->solver().setOptions(o);
      ElasticSolve solve(*s.system);
      try {
        solve.solve(0.0, false);
        ADD_FAILURE() << "a singular system was solved with " << method;
      } catch (const UserError& e) {
        const auto& d = e.diagnostics().front();
        EXPECT_EQ(d.id, "SOLVE_1") << method;
        EXPECT_NE(d.message.find("component DY is free"), std::string::npos) << method << ": " << d.message;
      }
    }
  }
}

// An iterative SOLVEUR (GCPC here; PETSC the same) that stops at NMAX_ITER before RESI_RELA: the
// backend's LinearSolverError becomes SOLVE_2 with the advice, at the solve as at the
// factorisation (it escaped as an internal error from STAT_NON_LINE's solves before).
TEST(StiffnessMatrix, IterativeSolveWithoutConvergenceIsSolve2) {
  Study s = study(CellType::QUAD4, 6, true);
  linalg::SolverOptions o;
  o.method = linalg::SolverMethod::Gcpc;
  o.relativeResidual = 1e-14;
  o.maxIterations = 1;
  s.system->solver().setOptions(o);
  ElasticSolve solve(*s.system);
  try {
    solve.solve(0.0, false);
    ADD_FAILURE() << "one GCPC iteration reached RESI_RELA = 1e-14";
  } catch (const UserError& e) {
    const auto& d = e.diagnostics().front();
    EXPECT_EQ(d.id, "SOLVE_2");
    EXPECT_NE(d.message.find("no convergence"), std::string::npos) << d.message;
  }
}

} // namespace
} // namespace stella
