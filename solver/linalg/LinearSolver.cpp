// The solver facade: method names and the choice of backend.

#include "solver/linalg/Backends.hpp"

#include <cmath>

namespace stella::linalg {

std::optional<SolverMethod> solverMethodFromName(std::string_view name) {
  if (name == "MUMPS") {
    return SolverMethod::Mumps;
  }
  if (name == "MULT_FRONT") {
    return SolverMethod::MultFront;
  }
  if (name == "LDLT") {
    return SolverMethod::Ldlt;
  }
  if (name == "GCPC") {
    return SolverMethod::Gcpc;
  }
  if (name == "PETSC") {
    return SolverMethod::Petsc;
  }
  return std::nullopt;
}

namespace {

std::unique_ptr<LinearSolver> makePetscFor(const SolverOptions& options, MatrixKind kind) {
  if (!petscAvailable()) {
    throw LinearSolverError(
        "METHODE='PETSC': this stella was built without PETSc (install petsc-dev, rebuild)");
  }
  if (kind == MatrixKind::SymmetricIndefinite) {
    throw LinearSolverError(
        "METHODE='PETSC' on a matrix with Lagrange multipliers (dualised relations) is not "
        "implemented yet: eliminate the conditions (AFFE_CHAR_CINE, or single-DOF DDL_IMPO, "
        "eliminated) or use MUMPS");
  }
  if (kind == MatrixKind::Unsymmetric && (options.algorithm == "CG" || options.preconditioner == "LDLT_SP" ||
                                          options.preconditioner == "LDLT_INC")) {
    throw LinearSolverError(
        "METHODE='PETSC' with ALGORITHME='" + options.algorithm + "', PRE_COND='" + options.preconditioner +
        "' needs a symmetric matrix: this tangent is unsymmetric (use GMRES, FGMRES or GCR "
        "with GAMG, BOOMER, ML, SOR or JACOBI)");
  }
  return detail::makePetsc(options, kind);
}

} // namespace

std::unique_ptr<LinearSolver> makeLinearSolver(const SolverOptions& options, MatrixKind kind) {
  switch (options.method) {
  case SolverMethod::Mumps:
    return detail::makeMumps(options, kind);
  case SolverMethod::MultFront:
  case SolverMethod::Ldlt:
    if (kind == MatrixKind::SymmetricPositiveDefinite) {
      return detail::makeCholmod(options);
    }
    return detail::makeUmfpack(options, kind);
  case SolverMethod::Gcpc:
    if (kind != MatrixKind::SymmetricPositiveDefinite) {
      throw LinearSolverError("GCPC needs a symmetric positive definite matrix: eliminate the "
                              "constraints (AFFE_CHAR_CINE) instead of dualising them, or use MUMPS");
    }
    if (options.preconditioner == "LDLT_SP") {
      return detail::makeSinglePrecisionPcg(options);
    }
    return detail::makeConjugateGradient(options);
  case SolverMethod::Petsc:
    return makePetscFor(options, kind);
  }
  throw LinearSolverError("unknown SOLVEUR METHODE");
}

namespace detail {

int firstNullPivot(const Eigen::Ref<const Eigen::VectorXd>& pivots, int nprec, double ratio) {
  if (pivots.size() == 0) {
    return -1;
  }
  const double largest = pivots.cwiseAbs().maxCoeff();
  // NPREC < 0 turns the detection off: only an exactly zero (or not finite) pivot is null
  const double threshold = nprec < 0 ? 0.0 : std::pow(10.0, -nprec) * largest / ratio;
  for (Eigen::Index k = 0; k < pivots.size(); ++k) {
    if (!(std::abs(pivots[k]) > threshold)) {
      return static_cast<int>(k);
    }
  }
  return -1;
}

} // namespace detail
} // namespace stella::linalg
