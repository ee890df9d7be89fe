// SOLVEUR RENUM: every ordering each backend offers gives the same solution (to 1e-10) on a 3D
// elastic cube, the backend reports using the ordering asked (Debian's sequential MUMPS has no
// METIS: it would silently take another, hence the catalogue refuses it); the reverse
// Cuthill-McKee ordering of RENUM='RCMK'; the BLAS thread count (STELLA_BLAS_THREADS, P ncpus).

#include "solver/linalg/Ordering.hpp"
#include "solver/linalg/BlasThreads.hpp"
#include "solver/linalg/LinearSolver.hpp"
#include "solver/linalg/MumpsOrderings.hpp"
#include "solver/linalg/tests/CubeSystem.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <random>

namespace stella::linalg {
namespace {

using stella::testing::BoxClamp;
using stella::testing::ElasticBox;

struct Case {
  SolverMethod method;
  const char* renum;
  const char* used; // the ordering the backend must report
};

Eigen::VectorXd solveWith(const Case& c, MatrixKind kind, const Cube& cube) {
  if (!mumpsOrderingAvailable(c.renum) && c.method == SolverMethod::Mumps) {
    // the parallel MUMPS (STELLA_MPI) has no SCOTCH: refused, never silently replaced
    SolverOptions o;
    o.renumbering = c.renum;
    EXPECT_THROW(makeLinearSolver(o, kind), LinearSolverError) << c.renum;
    return solveWith({c.method, "AMD", "AMD"}, kind, cube);
  }
  SolverOptions o;
  o.method = c.method;
  o.renumbering = c.renum;
  o.relativeResidual = 1e-14;
  auto s = makeLinearSolver(o, kind);
  s->analyse(cube.k);
  s->factorise(cube.k);
  Eigen::VectorXd u = cube.f;
  s->solve(u);
  if (c.method != SolverMethod::Gcpc) {
    EXPECT_EQ(s->orderingUsed(), c.used) << s->backendName() << " RENUM=" << c.renum;
    EXPECT_GT(s->factorisationFlops(), 0.0) << s->backendName();
  }
  return u;
}

// The catalogue's implemente= lists of RENUM (SOLVEUR.cata), backend by backend.
TEST(Renumbering, EveryOrderingGivesTheSameSolutionOnAnSpdCube) {
  const Cube cube(false);
  const Case cases[] = {{SolverMethod::Mumps, "AMD", "AMD"},
                        {SolverMethod::Mumps, "AMF", "AMF"},
                        {SolverMethod::Mumps, "PORD", "PORD"},
                        {SolverMethod::Mumps, "QAMD", "QAMD"},
                        {SolverMethod::Mumps, "SCOTCH", "SCOTCH"},
                        {SolverMethod::MultFront, "MDA", "AMD"},
                        {SolverMethod::MultFront, "METIS", "METIS"},
                        {SolverMethod::Ldlt, "RCMK", "GIVEN"},
                        {SolverMethod::Gcpc, "RCMK", ""}};
  const Eigen::VectorXd reference = solveWith(cases[6], MatrixKind::SymmetricPositiveDefinite, cube);
  ASSERT_GT(reference.norm(), 0.0);
  for (const Case& c : cases) {
    const Eigen::VectorXd u = solveWith(c, MatrixKind::SymmetricPositiveDefinite, cube);
    EXPECT_LT((u - reference).norm(), 1e-10 * reference.norm()) << c.renum;
  }
}

TEST(Renumbering, EveryOrderingGivesTheSameSolutionWithLagrangeMultipliers) {
  const Cube cube(true);
  const Case cases[] = {{SolverMethod::Mumps, "AMD", "AMD"},         {SolverMethod::Mumps, "AMF", "AMF"},
                        {SolverMethod::Mumps, "PORD", "PORD"},       {SolverMethod::Mumps, "QAMD", "QAMD"},
                        {SolverMethod::Mumps, "SCOTCH", "SCOTCH"},   {SolverMethod::MultFront, "MDA", "AMD"},
                        {SolverMethod::MultFront, "METIS", "METIS"}, {SolverMethod::Ldlt, "RCMK", "GIVEN"}};
  const Eigen::VectorXd reference = solveWith(cases[0], MatrixKind::SymmetricIndefinite, cube);
  for (const Case& c : cases) {
    const Eigen::VectorXd u = solveWith(c, MatrixKind::SymmetricIndefinite, cube);
    EXPECT_LT((u - reference).norm(), 1e-10 * reference.norm()) << c.renum;
  }
}

// What the libraries do not provide is refused by the backend too (the catalogue refuses it first).
TEST(Renumbering, UnknownOrderingsAreRefused) {
  for (auto [method, renum] : {std::pair{SolverMethod::Mumps, "PARMETIS"}, {SolverMethod::MultFront, "MD"}}) {
    SolverOptions o;
    o.method = method;
    o.renumbering = renum;
    EXPECT_THROW(makeLinearSolver(o, MatrixKind::SymmetricPositiveDefinite), LinearSolverError) << renum;
  }
}

// A 40 x 3 strip numbered along its length has a bandwidth of about 2 x 41 DOFs; reverse
// Cuthill-McKee, after any shuffle, numbers it across: a level holds at most 4 nodes (2 DOFs
// each), an entry spans two levels, so the bandwidth is below 2 x 4 x 2 = 16.
TEST(Renumbering, ReverseCuthillMcKeeNumbersAStripAcross) {
  fem::PlainMesh mesh = fem::boxMesh(CellType::QUAD4, {40, 3, 1}, {40.0, 3.0, 1.0});
  std::vector<int> shuffle(static_cast<std::size_t>(mesh.nodeCount()));
  std::iota(shuffle.begin(), shuffle.end(), 0);
  std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937(7));
  fem::PlainMesh shuffled = mesh; // node i becomes node shuffle[i]
  for (int i = 0; i < mesh.nodeCount(); ++i) {
    shuffled.coordinates.row(shuffle[static_cast<std::size_t>(i)]) = mesh.coordinates.row(i);
  }
  for (int& node : shuffled.connectivity) {
    node = shuffle[static_cast<std::size_t>(node)];
  }
  const ElasticBox strip(shuffled, BoxClamp{});
  const SparsePattern* pattern = &strip.matrix.pattern();
  std::vector<int> natural(static_cast<std::size_t>(pattern->size));
  std::iota(natural.begin(), natural.end(), 0);
  const std::vector<int> order = reverseCuthillMcKee(*pattern);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, natural); // a permutation
  EXPECT_LE(bandwidth(*pattern, order), 16);
  EXPECT_GT(bandwidth(*pattern, natural), 40); // the shuffle made it wide
}

TEST(BlasThreads, EnvironmentVariableThenExportCount) {
  unsetenv("STELLA_BLAS_THREADS");
  EXPECT_FALSE(blasThreadsFromEnvironment().has_value());
  EXPECT_EQ(blasThreadsFor(2), 2);
  EXPECT_EQ(applyBlasThreads(1), ""); // the default says nothing
  setenv("STELLA_BLAS_THREADS", "3", 1);
  EXPECT_EQ(blasThreadsFor(2), 3);
  for (const char* bad : {"0", "x", "2.5", "", "2000"}) {
    setenv("STELLA_BLAS_THREADS", bad, 1);
    EXPECT_THROW(blasThreadsFromEnvironment(), std::invalid_argument) << bad;
    EXPECT_NE(applyBlasThreads(1).find("not a whole number"), std::string::npos) << bad;
  }
  unsetenv("STELLA_BLAS_THREADS");
  setBlasThreads(1);
}

// With OpenBLAS's pthread variant (tools/install-deps) the count is set at run time.
TEST(BlasThreads, OpenBlasPthreadTakesTheCount) {
  if (blasDescription().find("SINGLE_THREADED") != std::string::npos || blasDescription().empty()) {
    GTEST_SKIP() << "serial BLAS: " << blasDescription();
  }
  EXPECT_EQ(setBlasThreads(2), 2);
  EXPECT_NE(applyBlasThreads(2).find("BLAS threads of the factorisations: 2 (P ncpus)"), std::string::npos);
  EXPECT_EQ(setBlasThreads(1), 1);
}

} // namespace
} // namespace stella::linalg
