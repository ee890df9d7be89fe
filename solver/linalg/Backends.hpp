#pragma once
// Constructors of the linear solver backends (internal to linalg/; use makeLinearSolver).

#include "solver/linalg/LinearSolver.hpp"

namespace stella::linalg::detail {

std::unique_ptr<LinearSolver> makeMumps(const SolverOptions& o, MatrixKind k);
std::unique_ptr<LinearSolver> makeCholmod(const SolverOptions& o);
std::unique_ptr<LinearSolver> makeUmfpack(const SolverOptions& o, MatrixKind k);
std::unique_ptr<LinearSolver> makeConjugateGradient(const SolverOptions& o);
std::unique_ptr<LinearSolver> makeSinglePrecisionPcg(const SolverOptions& o);  // GCPC + LDLT_SP
std::unique_ptr<LinearSolver> makePetsc(const SolverOptions& o, MatrixKind k); // PetscSolver.cpp

// Smallest pivot relative to the largest: index of the first |d_k| <= 10^-nprec max|d|, or -1.
// `ratio` (setPenaltyRatio) divides the threshold.
int firstNullPivot(const Eigen::Ref<const Eigen::VectorXd>& pivots, int nprec, double ratio = 1.0);

} // namespace stella::linalg::detail
