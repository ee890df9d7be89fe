// MUMPS's own SOLVEUR options (MumpsControls.hpp): each gives the default in-core solution to
// 1e-10, and each reaches MUMPS, seen in what MUMPS reports (INFOG). Block low-rank (LR) is
// refused by the catalogue (MUMPS 5.5.1's BLR clustering crashed in SCOTCH 7): not tested here.

#include "solver/linalg/MumpsControlsApply.hpp"
#include "solver/linalg/tests/CubeSystem.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace stella::linalg {
namespace {

struct Solved {
  Eigen::VectorXd u;
  std::unique_ptr<LinearSolver> solver;
};

Solved solveWith(const Cube& cube, MatrixKind kind, const MumpsControls& c,
                 SolverMethod method = SolverMethod::Mumps) {
  SolverOptions o;
  o.method = method;
  o.mumps = c;
  o.relativeResidual = 1e-12;
  if (method == SolverMethod::Gcpc) {
    o.preconditioner = "LDLT_SP";
    o.renumbering = "SANS";
  }
  Solved r{cube.f, makeLinearSolver(o, kind)};
  r.solver->analyse(cube.k);
  r.solver->factorise(cube.k);
  r.solver->solve(r.u);
  return r;
}

double relativeDifference(const Eigen::VectorXd& u, const Eigen::VectorXd& reference) {
  return (u - reference).norm() / reference.norm();
}

MumpsControls with(std::string memory, std::string acceleration = "AUTO", double threshold = 0.0,
                   std::string post = "AUTO") {
  MumpsControls c;
  c.memory = std::move(memory);
  c.acceleration = std::move(acceleration);
  c.lowRankThreshold = threshold;
  c.postprocessing = std::move(post);
  return c;
}

const Cube& largeCube() {
  static const Cube cube(false, {14, 12, 12}); // 7 605 equations
  return cube;
}

TEST(MumpsControls, FullRankOptionsGiveTheSameSolution) {
  for (bool lagrange : {false, true}) {
    const Cube cube(lagrange, {6, 5, 5});
    const MatrixKind kind =
        lagrange ? MatrixKind::SymmetricIndefinite : MatrixKind::SymmetricPositiveDefinite;
    const Solved reference = solveWith(cube, kind, with("IN_CORE"));
    MumpsControls sans = with("IN_CORE");
    sans.preprocessing = "SANS";
    MumpsControls checked = with("AUTO");
    checked.backwardErrorLimit = 1e-12;
    // PRETRAITEMENTS='SANS' (no matching, no scaling) on the saddle-point system: MUMPS meets
    // pivots under CNTL(3) (a null pivot, SOLVE_1 for a user: a clean error), hence SPD only
    std::vector<MumpsControls> variants{with("OUT_OF_CORE"),
                                        with("AUTO"),
                                        with("AUTO", "FR"),
                                        checked,
                                        with("IN_CORE", "AUTO", 0.0, "FORCE"),
                                        with("IN_CORE", "AUTO", 0.0, "MINI")};
    if (!lagrange) {
      variants.push_back(sans);
    }
    for (const MumpsControls& c : variants) {
      const Solved r = solveWith(cube, kind, c);
      EXPECT_LT(relativeDifference(r.u, reference.u), 1e-10)
          << c.memory << " " << c.acceleration << " " << c.preprocessing << " " << c.postprocessing;
    }
  }
}

// POSTTRAITEMENTS -> ICNTL(10): INFOG(15) counts the refinement steps MUMPS did: none with SANS,
// exactly one with MINI (ICNTL(10) = -1).
TEST(MumpsControls, RefinementStepsReachMumps) {
  const Cube cube(false, {6, 5, 5});
  const MatrixKind kind = MatrixKind::SymmetricPositiveDefinite;
  EXPECT_EQ(solveWith(cube, kind, with("IN_CORE", "AUTO", 0.0, "SANS")).solver->mumpsInfog(15), 0);
  EXPECT_EQ(solveWith(cube, kind, with("IN_CORE", "AUTO", 0.0, "MINI")).solver->mumpsInfog(15), 1);
}

// RESI_RELA > 0 (ICNTL(11) = 2): a backward error above it fails the solve. No factorisation in
// double precision reaches 1e-20 (the backward error is at least about the unit round-off, 1e-16);
// 1e-12 is met (measured 2e-16 after refinement).
TEST(MumpsControls, BackwardErrorAboveResiRelaFails) {
  const Cube& cube = largeCube();
  MumpsControls c = with("IN_CORE", "AUTO", 0.0, "SANS");
  c.backwardErrorLimit = 1e-20;
  EXPECT_THROW(solveWith(cube, MatrixKind::SymmetricPositiveDefinite, c), LinearSolverError);
  c.backwardErrorLimit = 1e-12;
  c.postprocessing = "AUTO"; // refinement towards the limit
  EXPECT_NO_THROW(solveWith(cube, MatrixKind::SymmetricPositiveDefinite, c));
}

// GESTION_MEMOIRE: out of core uses less memory in the factorisation (INFOG(22)) than in core; AUTO
// goes out of core when the analysis's estimate exceeds the memory available.
TEST(MumpsControls, OutOfCoreReachesMumps) {
  const Cube& cube = largeCube();
  const MatrixKind kind = MatrixKind::SymmetricPositiveDefinite;
  const Solved inCore = solveWith(cube, kind, with("IN_CORE"));
  const Solved outOfCore = solveWith(cube, kind, with("OUT_OF_CORE"));
  EXPECT_LT(outOfCore.solver->mumpsInfog(22), inCore.solver->mumpsInfog(22));
  EXPECT_LT(relativeDifference(outOfCore.u, inCore.u), 1e-10);

  struct Fake {
    int icntl[60] = {};
    int infog[80] = {};
  };
  Fake small, huge;
  small.infog[16] = 10;
  huge.infog[16] = 2'000'000'000;
  chooseMumpsMemory(small, with("AUTO"));
  chooseMumpsMemory(huge, with("AUTO"));
  EXPECT_EQ(small.icntl[21], 0);
  EXPECT_EQ(huge.icntl[21], 1);
  EXPECT_GT(availableMegabytes(), 0.0);
}

// PCENT_PIVOT -> ICNTL(14): the memory MUMPS allocates for the factorisation (INFOG(19), MB)
// grows with it.
TEST(MumpsControls, PivotPercentReachesMumps) {
  const Cube& cube = largeCube();
  SolverOptions o;
  long long memory[2] = {};
  for (int i = 0; i < 2; ++i) {
    o.pivotPercent = i == 0 ? 20.0 : 400.0;
    auto s = makeLinearSolver(o, MatrixKind::SymmetricPositiveDefinite);
    s->analyse(cube.k);
    s->factorise(cube.k);
    memory[i] = s->mumpsInfog(19);
  }
  EXPECT_GT(memory[1], memory[0]);
}

} // namespace
} // namespace stella::linalg
