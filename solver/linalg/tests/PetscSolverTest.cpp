// SOLVEUR METHODE='PETSC' (linalg/PetscSolver.cpp and its worker tools/petsc-worker): every
// ALGORITHME and PRE_COND implemented gives MUMPS's solution of a 3D elastic cube to the
// solver's tolerance, before and after a refactorisation; the rigid-body modes make GAMG
// converge in fewer iterations; a kept LDLT_SP preconditioner that no longer serves is rebuilt
// (REAC_PRECOND); unsymmetric systems with GMRES; what is not available is refused.

#include "solver/linalg/LinearSolver.hpp"
#include "solver/linalg/tests/ElasticBox.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella::linalg {
namespace {

// 3D elasticity of an n x n x 2n HEXA8 cube (E = 1000, nu = 0.3), numbered and assembled by
// the run's DofMap and StiffnessMatrix, clamped on z = 0 by elimination (unit diagonal), as
// stella's SaddleSolver gives it to the solvers (upper triangle, or in full).
struct Cube {
  stella::testing::ElasticBox box;
  SparseMatrix& matrix;
  std::vector<double> coordinates; // per equation: its node's coordinate along its component

  explicit Cube(int n, Storage storage = Storage::Upper)
      : box(fem::boxMesh(CellType::HEXA8, {n, n, 2 * n}, {1.0, 1.0, 2.0}),
            stella::testing::BoxClamp{stella::testing::Clamp::Eliminated, 2, 3, 1000.0, 0.3, storage}),
        matrix(box.matrix) {
    for (int i = 0; i < box.dofs().physicalCount(); ++i) {
      coordinates.push_back(box.coordinate(i));
    }
  }

  Eigen::MatrixXd rightHandSides() const {
    const int n = matrix.size();
    Eigen::MatrixXd b(n, 2);
    for (int i = 0; i < n; ++i) {
      b(i, 0) = std::sin(0.3 * i);
      b(i, 1) = (i % 3 == 0) ? 1.0 : 0.0;
    }
    return b;
  }
};

Eigen::MatrixXd solveWith(SolverOptions o, const SparseMatrix& a, const Eigen::MatrixXd& b,
                          MatrixKind kind = MatrixKind::SymmetricPositiveDefinite) {
  auto s = makeLinearSolver(o, kind);
  s->analyse(a);
  s->factorise(a);
  Eigen::MatrixXd x = b;
  s->solve(x);
  return x;
}

SolverOptions petsc(const std::string& algorithm, const std::string& preconditioner, double resi = 1e-10) {
  SolverOptions o;
  o.method = SolverMethod::Petsc;
  o.algorithm = algorithm;
  o.preconditioner = preconditioner;
  o.relativeResidual = resi;
  return o;
}

#define REQUIRE_PETSC()                                                                                      \
  if (!petscAvailable()) {                                                                                   \
    GTEST_SKIP() << "built without PETSc";                                                                   \
  }

// ||K (x - x_mumps)|| <= RESI_RELA ||b|| is what the Krylov solver guarantees; on this cube
// (condition number about 1e4) the relative error of x stays below 1e4 * RESI_RELA = 1e-6 and
// measured below 1e-8: the test asks 1e-7.
TEST(PetscSolver, EveryAlgorithmAndPreconditionerGivesMumpsSolution) {
  REQUIRE_PETSC();
  const Cube cube(4);
  const Eigen::MatrixXd b = cube.rightHandSides();
  const Eigen::MatrixXd reference = solveWith(SolverOptions{}, cube.matrix, b);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"CG", "GAMG"},       {"CG", "BOOMER"},  {"CG", "ML"},       {"FGMRES", "LDLT_SP"},
      {"CG", "LDLT_INC"},   {"CG", "SOR"},     {"CG", "JACOBI"},   {"GMRES", "GAMG"},
      {"FGMRES", "BOOMER"}, {"GCR", "JACOBI"}, {"FGMRES", "SANS"}, {"CG", "LDLT_SP"}};
  for (const auto& [algorithm, preconditioner] : cases) {
    auto s = makeLinearSolver(petsc(algorithm, preconditioner), MatrixKind::SymmetricPositiveDefinite);
    s->setNodeCoordinates(3, cube.coordinates);
    s->analyse(cube.matrix);
    s->factorise(cube.matrix);
    Eigen::MatrixXd x = b;
    s->solve(x);
    EXPECT_LT((x - reference).norm(), 1e-7 * reference.norm()) << algorithm << " + " << preconditioner;
    EXPECT_GT(s->lastIterations(), 0) << algorithm << " + " << preconditioner;
    // new values, same pattern: 2 K x = b
    SparseMatrix twice = cube.matrix;
    for (double& v : twice.values()) {
      v *= 2.0;
    }
    s->factorise(twice);
    Eigen::MatrixXd y = b;
    s->solve(y);
    EXPECT_LT((2.0 * y - reference).norm(), 1e-7 * reference.norm()) << algorithm << " + " << preconditioner;
  }
}

// The near-null space is what makes smoothed aggregation work on elasticity: GAMG with the six
// rigid-body modes needs fewer iterations than with the constant vectors PETSc takes without
// them (measured on this cube: see the test's output).
TEST(PetscSolver, RigidBodyModesHelpGamg) {
  REQUIRE_PETSC();
  const Cube cube(8);
  const Eigen::MatrixXd b = cube.rightHandSides().col(0);
  int iterations[2] = {0, 0};
  for (int withModes : {0, 1}) {
    auto s = makeLinearSolver(petsc("CG", "GAMG", 1e-8), MatrixKind::SymmetricPositiveDefinite);
    if (withModes != 0) {
      s->setNodeCoordinates(3, cube.coordinates);
    }
    s->analyse(cube.matrix);
    s->factorise(cube.matrix);
    Eigen::MatrixXd x = b;
    s->solve(x);
    iterations[withModes] = s->lastIterations();
  }
  std::printf("GAMG iterations without / with the rigid-body modes: %d / %d\n", iterations[0], iterations[1]);
  EXPECT_LT(iterations[1], iterations[0]);
}

// REAC_PRECOND with LDLT_SP: the preconditioner of K is kept for the next matrix; when it no
// longer serves (here K with a much stiffer half, NMAX_ITER = 3) the solve is retried with a
// fresh preconditioner and gives the direct solution; without the retry it would not converge.
TEST(PetscSolver, KeptSinglePrecisionPreconditionerIsRebuiltWhenItFails) {
  REQUIRE_PETSC();
  const Cube cube(4);
  SparseMatrix stiffer = cube.matrix;
  const SparsePattern& p = stiffer.pattern();
  for (int i = p.size / 2; i < p.size; ++i) {
    for (std::int64_t e = p.rowStart[static_cast<std::size_t>(i)];
         e < p.rowStart[static_cast<std::size_t>(i) + 1]; ++e) {
      stiffer.values()[static_cast<std::size_t>(e)] *= 1000.0;
    }
  }
  const Eigen::MatrixXd b = cube.rightHandSides();
  const Eigen::MatrixXd reference = solveWith(SolverOptions{}, stiffer, b);
  SolverOptions o = petsc("CG", "LDLT_SP", 1e-10);
  o.maxIterations = 3;
  auto s = makeLinearSolver(o, MatrixKind::SymmetricPositiveDefinite);
  s->analyse(cube.matrix);
  s->factorise(cube.matrix);
  Eigen::MatrixXd x = b;
  s->solve(x); // converges in 1 or 2 iterations: the preconditioner is kept
  s->factorise(stiffer);
  Eigen::MatrixXd y = b;
  s->solve(y);
  EXPECT_LT((y - reference).norm(), 1e-7 * reference.norm());
  EXPECT_LE(s->lastIterations(), 3);
}

TEST(PetscSolver, UnsymmetricWithGmres) {
  REQUIRE_PETSC();
  Cube cube(3, Storage::Full);
  // a small unsymmetric perturbation of the full matrix
  const SparsePattern& p = cube.matrix.pattern();
  for (int i = 0; i < p.size; ++i) {
    for (std::int64_t e = p.rowStart[static_cast<std::size_t>(i)];
         e < p.rowStart[static_cast<std::size_t>(i) + 1]; ++e) {
      if (p.columns[static_cast<std::size_t>(e)] > i) {
        cube.matrix.values()[static_cast<std::size_t>(e)] *= 1.1;
      }
    }
  }
  const Eigen::MatrixXd b = cube.rightHandSides();
  const Eigen::MatrixXd reference = solveWith(SolverOptions{}, cube.matrix, b, MatrixKind::Unsymmetric);
  for (const std::string algorithm : {"GMRES", "FGMRES", "GCR"}) {
    const Eigen::MatrixXd x = solveWith(petsc(algorithm, "JACOBI"), cube.matrix, b, MatrixKind::Unsymmetric);
    EXPECT_LT((x - reference).norm(), 1e-7 * reference.norm()) << algorithm;
  }
  EXPECT_THROW(makeLinearSolver(petsc("CG", "JACOBI"), MatrixKind::Unsymmetric), LinearSolverError);
  EXPECT_THROW(makeLinearSolver(petsc("GMRES", "LDLT_SP"), MatrixKind::Unsymmetric), LinearSolverError);
  EXPECT_THROW(makeLinearSolver(petsc("CG", "GAMG"), MatrixKind::SymmetricIndefinite), LinearSolverError);
}

// No convergence within NMAX_ITER: a LinearSolverError naming PETSc's reason; OPTION_PETSC
// reaches PETSc (a misspelt type is PETSc's error, reported).
TEST(PetscSolver, FailuresAreReported) {
  REQUIRE_PETSC();
  const Cube cube(4);
  const Eigen::MatrixXd b = cube.rightHandSides();
  SolverOptions o = petsc("CG", "JACOBI", 1e-12);
  o.maxIterations = 2;
  try {
    solveWith(o, cube.matrix, b);
    ADD_FAILURE() << "expected no convergence";
  } catch (const LinearSolverError& e) {
    EXPECT_NE(std::string(e.what()).find("DIVERGED_ITS"), std::string::npos) << e.what();
  }
  SolverOptions bad = petsc("CG", "JACOBI");
  bad.petscOptions = "-ksp_type no_such_ksp";
  EXPECT_THROW(solveWith(bad, cube.matrix, b), LinearSolverError);
}

} // namespace
} // namespace stella::linalg
