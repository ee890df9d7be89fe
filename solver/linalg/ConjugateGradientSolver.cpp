// GCPC: Eigen's conjugate gradient with an incomplete Cholesky preconditioner, on the upper
// triangle of a symmetric positive definite matrix.

#include "solver/linalg/Backends.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

namespace stella::linalg::detail {
namespace {

class ConjugateGradientSolver final : public LinearSolver {
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

public:
  explicit ConjugateGradientSolver(const SolverOptions& o)
      : LinearSolver(MatrixKind::SymmetricPositiveDefinite), options_(o) {}

  std::string_view backendName() const override { return "GCPC"; }
  double factorisationFlops() const override { return 0.0; } // incomplete Cholesky: not counted
  std::string orderingUsed() const override { return "none"; }

  void analyse(const SparseMatrix& a) override {
    if (a.storage() != Storage::Upper) {
      throw LinearSolverError("GCPC: needs upper-triangle storage");
    }
  }

  void factorise(const SparseMatrix& a) override {
    const SparsePattern& p = a.pattern();
    matrix_ = Eigen::Map<const Matrix>(p.size, p.size, static_cast<int>(p.nonZeros()), outer(p).data(),
                                       p.columns.data(), a.values().data());
    solver_.setTolerance(options_.relativeResidual);
    solver_.setMaxIterations(options_.maxIterations > 0 ? options_.maxIterations : p.size);
    solver_.compute(matrix_);
    if (solver_.info() != Eigen::Success) {
      throw SingularMatrixError("GCPC", -1);
    }
  }

  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override {
    for (Eigen::Index c = 0; c < rhs.cols(); ++c) {
      const Eigen::VectorXd b = rhs.col(c);
      const Eigen::VectorXd x = solver_.solve(b);
      if (solver_.info() != Eigen::Success) {
        throw LinearSolverError("GCPC: no convergence in " + std::to_string(solver_.iterations()) +
                                " iterations (relative residual " + std::to_string(solver_.error()) + ")");
      }
      rhs.col(c) = x;
    }
  }

private:
  const std::vector<int>& outer(const SparsePattern& p) {
    outer_.assign(p.rowStart.begin(), p.rowStart.end());
    return outer_;
  }

  SolverOptions options_;
  std::vector<int> outer_;
  Matrix matrix_;
  Eigen::ConjugateGradient<Matrix, Eigen::Upper, Eigen::IncompleteCholesky<double, Eigen::Upper>> solver_;
};

} // namespace

std::unique_ptr<LinearSolver> makeConjugateGradient(const SolverOptions& o) {
  return std::make_unique<ConjugateGradientSolver>(o);
}

} // namespace stella::linalg::detail
