// GCPC: Eigen's conjugate gradient with an incomplete Cholesky preconditioner, on the upper
// triangle of a symmetric positive definite matrix.

#include "solver/linalg/Backends.hpp"
#include "solver/linalg/Ordering.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

namespace stella::linalg::detail {
namespace {

// RENUM='RCMK' for Eigen's incomplete Cholesky: its ordering functors return the permutation
// whose k-th index is the equation placed k-th (what reverseCuthillMcKee gives).
struct ReverseCuthillMcKeeOrdering {
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;
  template <class View> void operator()(const View& view, PermutationType& perm) const {
    Eigen::SparseMatrix<double, Eigen::RowMajor, int> full;
    full = view;
    full.makeCompressed();
    SparsePattern p;
    p.size = static_cast<int>(full.rows());
    p.storage = Storage::Full;
    p.rowStart.assign(full.outerIndexPtr(), full.outerIndexPtr() + full.rows() + 1);
    p.columns.assign(full.innerIndexPtr(), full.innerIndexPtr() + full.nonZeros());
    const std::vector<int> order = reverseCuthillMcKee(p);
    perm.resize(p.size);
    for (int k = 0; k < p.size; ++k) {
      perm.indices()[k] = order[static_cast<std::size_t>(k)];
    }
  }
};

class ConjugateGradientSolver final : public LinearSolver {
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

public:
  explicit ConjugateGradientSolver(const SolverOptions& o)
      : LinearSolver(MatrixKind::SymmetricPositiveDefinite), options_(o) {}

  std::string_view backendName() const override { return "GCPC"; }
  double factorisationFlops() const override { return 0.0; } // incomplete Cholesky: not counted
  std::string orderingUsed() const override { return "none"; }
  std::string summary() const override {
    return lastIterations_ > 0
               ? std::to_string(lastIterations_) + " conjugate gradient iterations (incomplete Cholesky)"
               : "";
  }

  void analyse(const SparseMatrix& a) override {
    if (a.storage() != Storage::Upper) {
      throw LinearSolverError("GCPC: needs upper-triangle storage");
    }
  }

  void factorise(const SparseMatrix& a) override {
    const SparsePattern& p = a.pattern();
    matrix_ = Eigen::Map<const Matrix>(p.size, p.size, static_cast<int>(p.nonZeros()), outer(p).data(),
                                       p.columns.data(), a.values().data());
    if (options_.renumbering == "RCMK") {
      compute(rcm_, p.size);
    } else {
      compute(amd_, p.size);
    }
  }

  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override {
    if (options_.renumbering == "RCMK") {
      solveWith(rcm_, rhs);
    } else {
      solveWith(amd_, rhs);
    }
  }

private:
  template <class Solver> void compute(Solver& solver, int size) {
    solver.setTolerance(options_.relativeResidual);
    solver.setMaxIterations(options_.maxIterations > 0 ? options_.maxIterations : size);
    solver.compute(matrix_);
    if (solver.info() != Eigen::Success) {
      throw SingularMatrixError("GCPC", -1);
    }
  }

  template <class Solver> void solveWith(Solver& solver, Eigen::Ref<Eigen::MatrixXd> rhs) {
    for (Eigen::Index c = 0; c < rhs.cols(); ++c) {
      const Eigen::VectorXd b = rhs.col(c);
      const Eigen::VectorXd x = solver.solve(b);
      if (solver.info() != Eigen::Success) {
        throw LinearSolverError("GCPC: no convergence in " + std::to_string(solver.iterations()) +
                                " iterations (relative residual " + std::to_string(solver.error()) + ")");
      }
      rhs.col(c) = x;
      lastIterations_ = static_cast<int>(solver.iterations());
    }
  }

  const std::vector<int>& outer(const SparsePattern& p) {
    outer_.assign(p.rowStart.begin(), p.rowStart.end());
    return outer_;
  }

  SolverOptions options_;
  int lastIterations_ = 0;
  std::vector<int> outer_;
  Matrix matrix_;
  // RENUM: 'RCMK' (the catalogue's, code_aster's) or AMD (Eigen's default, for other callers)
  Eigen::ConjugateGradient<Matrix, Eigen::Upper, Eigen::IncompleteCholesky<double, Eigen::Upper>> amd_;
  Eigen::ConjugateGradient<Matrix, Eigen::Upper,
                           Eigen::IncompleteCholesky<double, Eigen::Upper, ReverseCuthillMcKeeOrdering>>
      rcm_;
};

} // namespace

std::unique_ptr<LinearSolver> makeConjugateGradient(const SolverOptions& o) {
  return std::make_unique<ConjugateGradientSolver>(o);
}

} // namespace stella::linalg::detail
