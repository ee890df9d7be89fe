// CHOLMOD supernodal LL^T backend for symmetric positive definite matrices (MULT_FRONT, LDLT).
// The pattern's upper rows are the lower columns of a CSC matrix (stype = -1).

#include "solver/linalg/Backends.hpp"
#include "solver/linalg/Ordering.hpp"

#include <cholmod.h>

#include <vector>

namespace stella::linalg::detail {
namespace {

class CholmodSolver final : public LinearSolver {
public:
  explicit CholmodSolver(const SolverOptions& o)
      : LinearSolver(MatrixKind::SymmetricPositiveDefinite), options_(o) {
    cholmod_start(&common_);
    common_.supernodal = CHOLMOD_SUPERNODAL;
    common_.final_ll = 1;
    common_.print = 0;
    common_.error_handler = nullptr;
    // RENUM (SOLVEUR.cata): METIS nested dissection; MDA (MULT_FRONT) or AMD: approximate minimum
    // degree; RCMK (LDLT): reverse Cuthill-McKee given as the permutation; AUTO: CHOLMOD's choice
    // (AMD, then METIS when AMD's fill is large).
    const std::string& r = o.renumbering;
    if (r == "METIS" || r == "MDA" || r == "AMD" || r == "RCMK") {
      common_.nmethods = 1;
      common_.method[0].ordering = r == "METIS" ? CHOLMOD_METIS : r == "RCMK" ? CHOLMOD_GIVEN : CHOLMOD_AMD;
      common_.postorder = 1;
    } else if (r != "AUTO") {
      throw LinearSolverError("CHOLMOD: RENUM='" + r + "' is not available (METIS, MDA, AMD, RCMK or AUTO)");
    }
  }
  ~CholmodSolver() override {
    if (factor_ != nullptr) {
      cholmod_free_factor(&factor_, &common_);
    }
    cholmod_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  std::string_view backendName() const override { return "CHOLMOD"; }
  double factorisationFlops() const override { return factorised_ ? common_.fl : 0.0; }
  std::string orderingUsed() const override {
    if (factor_ == nullptr) {
      return "none";
    }
    switch (factor_->ordering) {
    case CHOLMOD_NATURAL:
      return "NATURAL";
    case CHOLMOD_GIVEN:
      return "GIVEN";
    case CHOLMOD_AMD:
      return "AMD";
    case CHOLMOD_METIS:
      return "METIS";
    case CHOLMOD_NESDIS:
      return "NESDIS";
    default:
      return "other";
    }
  }

  void analyse(const SparseMatrix& a) override {
    if (a.storage() != Storage::Upper) {
      throw LinearSolverError("CHOLMOD: needs upper-triangle storage");
    }
    const SparsePattern& p = a.pattern();
    rowStart_.assign(p.rowStart.begin(), p.rowStart.end());
    if (p.nonZeros() > static_cast<std::int64_t>(0x7fffffff)) {
      throw LinearSolverError("CHOLMOD: more than 2^31 non-zeros");
    }
    view(a);
    if (factor_ != nullptr) {
      cholmod_free_factor(&factor_, &common_);
    }
    if (options_.renumbering == "RCMK") {
      std::vector<int> order = reverseCuthillMcKee(p);
      factor_ = cholmod_analyze_p(&matrix_, order.data(), nullptr, 0, &common_);
    } else {
      factor_ = cholmod_analyze(&matrix_, &common_);
    }
    if (factor_ == nullptr || common_.status < CHOLMOD_OK) {
      throw LinearSolverError("CHOLMOD: analysis failed (status " + std::to_string(common_.status) + ")");
    }
  }

  void factorise(const SparseMatrix& a) override {
    view(a);
    cholmod_factorize(&matrix_, factor_, &common_);
    if (common_.status == CHOLMOD_NOT_POSDEF) {
      const auto* perm = static_cast<const int*>(factor_->Perm);
      throw SingularMatrixError("CHOLMOD",
                                perm != nullptr ? perm[factor_->minor] : static_cast<int>(factor_->minor));
    }
    factorised_ = common_.status >= CHOLMOD_OK;
    if (common_.status < CHOLMOD_OK) {
      throw LinearSolverError("CHOLMOD: factorisation failed (status " + std::to_string(common_.status) +
                              ")");
    }
    if (options_.stopIfSingular) {
      const Eigen::VectorXd d = diagonal();
      const int k = firstNullPivot(d.cwiseProduct(d), options_.nprec, penaltyRatio_);
      if (k >= 0) {
        throw SingularMatrixError("CHOLMOD", static_cast<const int*>(factor_->Perm)[k]);
      }
    }
  }

  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override {
    Eigen::MatrixXd b = rhs;
    cholmod_dense dense{};
    dense.nrow = static_cast<std::size_t>(b.rows());
    dense.ncol = static_cast<std::size_t>(b.cols());
    dense.nzmax = dense.nrow * dense.ncol;
    dense.d = dense.nrow;
    dense.x = b.data();
    dense.xtype = CHOLMOD_REAL;
    dense.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor_, &dense, &common_);
    if (x == nullptr) {
      throw LinearSolverError("CHOLMOD: solution failed");
    }
    rhs = Eigen::Map<Eigen::MatrixXd>(static_cast<double*>(x->x), b.rows(), b.cols());
    cholmod_free_dense(&x, &common_);
  }

private:
  // Diagonal of L (supernodal, in the factor's pivot order).
  Eigen::VectorXd diagonal() const {
    Eigen::VectorXd d(static_cast<Eigen::Index>(factor_->n));
    const auto* super = static_cast<const int*>(factor_->super);
    const auto* pi = static_cast<const int*>(factor_->pi);
    const auto* px = static_cast<const int*>(factor_->px);
    const auto* x = static_cast<const double*>(factor_->x);
    for (std::size_t s = 0; s < factor_->nsuper; ++s) {
      const int k1 = super[s], k2 = super[s + 1];
      const int nsrow = pi[s + 1] - pi[s];
      for (int k = k1; k < k2; ++k) {
        d[k] = x[px[s] + (k - k1) * nsrow + (k - k1)];
      }
    }
    return d;
  }

  void view(const SparseMatrix& a) {
    const SparsePattern& p = a.pattern();
    matrix_ = {};
    matrix_.nrow = static_cast<std::size_t>(p.size);
    matrix_.ncol = static_cast<std::size_t>(p.size);
    matrix_.nzmax = static_cast<std::size_t>(p.nonZeros());
    matrix_.p = rowStart_.data();
    matrix_.i = const_cast<int*>(p.columns.data());
    matrix_.x = const_cast<double*>(a.values().data());
    matrix_.stype = -1;
    matrix_.itype = CHOLMOD_INT;
    matrix_.xtype = CHOLMOD_REAL;
    matrix_.dtype = CHOLMOD_DOUBLE;
    matrix_.sorted = 1;
    matrix_.packed = 1;
  }

  SolverOptions options_;
  cholmod_common common_{};
  cholmod_sparse matrix_{};
  cholmod_factor* factor_ = nullptr;
  std::vector<int> rowStart_;
  bool factorised_ = false;
};

} // namespace

std::unique_ptr<LinearSolver> makeCholmod(const SolverOptions& o) {
  return std::make_unique<CholmodSolver>(o);
}

} // namespace stella::linalg::detail
