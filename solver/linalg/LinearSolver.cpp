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
    break;
  }
  throw LinearSolverError("METHODE='PETSC' is not implemented yet");
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
