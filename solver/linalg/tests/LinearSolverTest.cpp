// Linear algebra tests: the run's in-place assembly (StiffnessMatrix, DofMap numbering) against a
// dense assembly of the element matrices; every backend on
// SPD, saddle-point (dualised Lagrange) and unsymmetric systems against dense Eigen solutions,
// with refactorisation and blocks of right-hand sides; singular matrices reported with the
// equation of a free DOF.

#include "solver/linalg/LinearSolver.hpp"
#include "solver/linalg/tests/ElasticBox.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella::linalg {
namespace {

using stella::testing::BoxClamp;
using stella::testing::Clamp;
using stella::testing::ElasticBox;

// Plane-strain elasticity of a 4 x 3 QUAD8 mesh of [0,1]^2 (E = 1000, nu = 0.3), numbered and
// assembled by the run's DofMap and StiffnessMatrix, optionally with Lagrange multipliers
// blocking DX (and DY unless floatY) of the nodes on x = 0.
ElasticBox problem(bool lagrange, bool floatY, Storage storage) {
  BoxClamp c;
  c.kind = lagrange ? Clamp::Dualised : Clamp::Free;
  c.components = floatY ? 1 : 2;
  c.storage = storage;
  c.withDense = true;
  return ElasticBox(fem::boxMesh(CellType::QUAD8, {4, 3, 1}, {1.0, 1.0, 1.0}), c);
}

Eigen::MatrixXd rightHandSides(int n) {
  Eigen::MatrixXd b(n, 3);
  for (int i = 0; i < n; ++i) {
    b(i, 0) = std::sin(0.3 * i);
    b(i, 1) = 1.0;
    b(i, 2) = (i % 7) - 3.0;
  }
  return b;
}

void expectSolves(LinearSolver& s, const SparseMatrix& a, const Eigen::MatrixXd& dense, double tol) {
  s.analyse(a);
  s.factorise(a);
  const Eigen::MatrixXd b = rightHandSides(a.size());
  const Eigen::MatrixXd reference = dense.fullPivLu().solve(b);
  Eigen::MatrixXd x = b;
  s.solve(x);
  EXPECT_LT((x - reference).norm(), tol * reference.norm()) << s.backendName();
  // refactorise new values with the same pattern and solve one column many times
  SparseMatrix twice = a;
  for (double& v : twice.values()) {
    v *= 2.0;
  }
  s.factorise(twice);
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd y = b.col(k);
    s.solve(y);
    EXPECT_LT((y - 0.5 * reference.col(k)).norm(), tol * reference.col(k).norm()) << s.backendName();
  }
}

TEST(SparseAssembly, InPlaceAssemblyMatchesDenseAssemblyInBothStorages) {
  for (Storage st : {Storage::Full, Storage::Upper}) {
    ElasticBox p = problem(true, false, st);
    EXPECT_LT((p.matrix.toDense() - p.dense).cwiseAbs().maxCoeff(), 1e-12 * p.dense.cwiseAbs().maxCoeff());
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(p.matrix.size(), -1.0, 2.0);
    EXPECT_LT((p.matrix.multiply(x) - p.dense * x).norm(), 1e-12 * (p.dense * x).norm());
  }
}

TEST(LinearSolver, SymmetricPositiveDefiniteEveryBackend) {
  // SPD: the elasticity matrix plus a small mass-like diagonal
  ElasticBox p = problem(false, false, Storage::Upper);
  for (int i = 0; i < p.matrix.size(); ++i) {
    p.matrix.add(i, i, 10.0);
    p.dense(i, i) += 10.0;
  }
  for (SolverMethod m :
       {SolverMethod::Mumps, SolverMethod::MultFront, SolverMethod::Ldlt, SolverMethod::Gcpc}) {
    SolverOptions o;
    o.method = m;
    o.relativeResidual = 1e-13;
    auto s = makeLinearSolver(o, MatrixKind::SymmetricPositiveDefinite);
    expectSolves(*s, p.matrix, p.dense, m == SolverMethod::Gcpc ? 1e-9 : 1e-11);
  }
}

// GCPC with PRE_COND='LDLT_SP': a conjugate gradient preconditioned by a single-precision MUMPS
// factorisation reaches the dense solution to the relative residual asked; the refactorisation
// of 2 K in expectSolves keeps the preconditioner of K (REAC_PRECOND: the first solves converged
// in a few iterations) and still converges. With REAC_PRECOND = 1 it is rebuilt: same solutions.
TEST(LinearSolver, GcpcWithSinglePrecisionPreconditioner) {
  ElasticBox p = problem(false, false, Storage::Upper);
  for (int i = 0; i < p.matrix.size(); ++i) {
    p.matrix.add(i, i, 10.0);
    p.dense(i, i) += 10.0;
  }
  for (int reuse : {30, 1}) {
    SolverOptions o;
    o.method = SolverMethod::Gcpc;
    o.preconditioner = "LDLT_SP";
    o.renumbering = "SANS";
    o.relativeResidual = 1e-13;
    o.preconditionerReuseIterations = reuse;
    auto s = makeLinearSolver(o, MatrixKind::SymmetricPositiveDefinite);
    EXPECT_EQ(s->backendName(), "GCPC (LDLT_SP)");
    expectSolves(*s, p.matrix, p.dense, 1e-10);
  }
  SolverOptions metis;
  metis.method = SolverMethod::Gcpc;
  metis.preconditioner = "LDLT_SP";
  metis.renumbering = "METIS";
  EXPECT_THROW(makeLinearSolver(metis, MatrixKind::SymmetricPositiveDefinite), LinearSolverError);
}

TEST(LinearSolver, SaddlePointWithLagrangeMultipliers) {
  ElasticBox p = problem(true, false, Storage::Upper);
  for (SolverMethod m : {SolverMethod::Mumps, SolverMethod::MultFront, SolverMethod::Ldlt}) {
    SolverOptions o;
    o.method = m;
    auto s = makeLinearSolver(o, MatrixKind::SymmetricIndefinite);
    expectSolves(*s, p.matrix, p.dense, 1e-10);
  }
  SolverOptions gcpc;
  gcpc.method = SolverMethod::Gcpc;
  EXPECT_THROW(makeLinearSolver(gcpc, MatrixKind::SymmetricIndefinite), LinearSolverError);
}

// Blocks of very sparse right-hand sides (a few entries per column, like the columns of A^T of
// discrete contact) go to MUMPS as sparse right-hand sides: the same solutions as the dense
// solve, including empty columns and the multipliers' rows of a saddle-point system.
TEST(LinearSolver, SparseRightHandSideBlocksSolveLikeDenseOnes) {
  for (bool lagrange : {false, true}) {
    ElasticBox p = problem(lagrange, false, Storage::Upper);
    if (!lagrange) {
      for (int i = 0; i < p.matrix.size(); ++i) {
        p.matrix.add(i, i, 10.0);
        p.dense(i, i) += 10.0;
      }
    }
    SolverOptions o;
    o.method = SolverMethod::Mumps;
    auto s = makeLinearSolver(o, lagrange ? MatrixKind::SymmetricIndefinite
                                          : MatrixKind::SymmetricPositiveDefinite);
    s->analyse(p.matrix);
    s->factorise(p.matrix);
    const int n = p.matrix.size();
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(n, 12);
    for (int j = 0; j < 11; ++j) { // column 11 stays empty
      b((7 * j) % n, j) = 1.0 + j;
      b((7 * j + 3) % n, j) = -0.5;
    }
    ASSERT_LT((b.array() != 0.0).count() * 20, b.size()); // sparse enough for the sparse path
    const Eigen::MatrixXd reference = p.dense.fullPivLu().solve(b);
    Eigen::MatrixXd x = b;
    s->solve(x);
    EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << (lagrange ? "saddle" : "SPD");
    EXPECT_EQ(x.col(11).cwiseAbs().maxCoeff(), 0.0);
  }
}

TEST(LinearSolver, UnsymmetricSystems) {
  ElasticBox p = problem(true, false, Storage::Full);
  // a friction-like unsymmetric coupling: K(i, i+2) += 0.3 k_ii for entries in the pattern
  const SparsePattern& pat = p.matrix.pattern();
  for (int i = 0; i + 2 < p.dofs().physicalCount(); ++i) {
    const auto k = pat.find(i, i + 2);
    if (k >= 0) {
      const double v = 0.3 * p.dense(i, i);
      p.matrix.values()[static_cast<std::size_t>(k)] += v;
      p.dense(i, i + 2) += v;
    }
  }
  for (SolverMethod m : {SolverMethod::Mumps, SolverMethod::Ldlt}) {
    SolverOptions o;
    o.method = m;
    auto s = makeLinearSolver(o, MatrixKind::Unsymmetric);
    expectSolves(*s, p.matrix, p.dense, 1e-10);
  }
}

TEST(LinearSolver, SingularMatrixNamesAFreeDof) {
  // floating body (no constraint), SPD solvers
  {
    ElasticBox p = problem(false, false, Storage::Upper);
    for (SolverMethod m : {SolverMethod::Mumps, SolverMethod::MultFront}) {
      SolverOptions o;
      o.method = m;
      auto s = makeLinearSolver(o, MatrixKind::SymmetricPositiveDefinite);
      s->analyse(p.matrix);
      try {
        s->factorise(p.matrix);
        ADD_FAILURE() << s->backendName() << " accepted a singular matrix";
      } catch (const SingularMatrixError& e) {
        EXPECT_GE(e.equation(), 0) << s->backendName();
        EXPECT_LT(e.equation(), p.dofs().physicalCount()) << s->backendName();
      }
    }
  }
  // DX blocked on x = 0 by multipliers but DY free: the rigid translation along Y remains
  ElasticBox p = problem(true, true, Storage::Upper);
  for (SolverMethod m : {SolverMethod::Mumps, SolverMethod::Ldlt}) {
    SolverOptions o;
    o.method = m;
    auto s = makeLinearSolver(o, MatrixKind::SymmetricIndefinite);
    s->analyse(p.matrix);
    try {
      s->factorise(p.matrix);
      ADD_FAILURE() << s->backendName() << " accepted a singular matrix";
    } catch (const SingularMatrixError& e) {
      ASSERT_GE(e.equation(), 0) << s->backendName();
      ASSERT_LT(e.equation(), p.dofs().physicalCount()) << s->backendName();
      const std::string dof = p.dofs().describe(e.equation(), *p.mesh);
      EXPECT_EQ(p.dofs().component(e.equation()), 1) << s->backendName() << ": " << dof;
      EXPECT_NE(dof.find("component DY"), std::string::npos) << dof;
      EXPECT_NE(dof.find("node N"), std::string::npos) << dof;
    }
  }
}

// A floating body held by a spring 1e-12 times the stiffness: NPREC = 8 (default) reports the
// near-null pivot as a singular matrix; a negative NPREC turns the detection off (code_aster's
// convention) and the system is solved.
TEST(LinearSolver, NegativeNprecTurnsNullPivotDetectionOff) {
  ElasticBox p = problem(false, false, Storage::Upper);
  const double spring = 1e-12 * p.dense.diagonal().maxCoeff();
  for (int i = 0; i < p.matrix.size(); ++i) {
    p.matrix.add(i, i, spring);
    p.dense(i, i) += spring;
  }
  for (SolverMethod m : {SolverMethod::Mumps, SolverMethod::MultFront}) {
    SolverOptions o;
    o.method = m;
    auto detecting = makeLinearSolver(o, MatrixKind::SymmetricPositiveDefinite);
    detecting->analyse(p.matrix);
    EXPECT_THROW(detecting->factorise(p.matrix), SingularMatrixError) << detecting->backendName();
    o.nprec = -1;
    auto s = makeLinearSolver(o, MatrixKind::SymmetricPositiveDefinite);
    s->analyse(p.matrix);
    ASSERT_NO_THROW(s->factorise(p.matrix)) << s->backendName();
    // a load with no resultant: the solution is well defined up to the weak spring's mode
    Eigen::VectorXd b = Eigen::VectorXd::Zero(p.matrix.size());
    b[0] = 1.0;
    b[2] = -1.0;
    Eigen::MatrixXd x = b;
    s->solve(x);
    // backward stable: the residual is at round-off level relative to |A| |x|
    EXPECT_LT((p.dense * x - b).norm(), 1e-10 * p.dense.norm() * x.norm()) << s->backendName();
  }
}

TEST(LinearSolver, PetscRefusesUnsymmetricSystems) {
  SolverOptions petsc;
  petsc.method = SolverMethod::Petsc;
  EXPECT_THROW(makeLinearSolver(petsc, MatrixKind::Unsymmetric), LinearSolverError);
}

} // namespace
} // namespace stella::linalg
