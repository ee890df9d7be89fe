// UMFPACK LU backend for symmetric indefinite (Lagrange multipliers) and unsymmetric matrices
// (MULT_FRONT, LDLT). The matrix rows (CSR) are the columns of A^T in CSC, so systems are solved
// with UMFPACK_At. Upper-triangle storage is expanded to full once, at analysis.

#include "solver/linalg/Backends.hpp"
#include "solver/linalg/Ordering.hpp"

#include <umfpack.h>

#include <vector>

namespace stella::linalg::detail {
namespace {

class UmfpackSolver final : public LinearSolver {
public:
  UmfpackSolver(const SolverOptions& o, MatrixKind k) : LinearSolver(k), options_(o) {
    umfpack_di_defaults(control_);
    if (k == MatrixKind::SymmetricIndefinite) {
      control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
    }
    // RENUM as for CHOLMOD (CholmodSolver.cpp): METIS, MDA/AMD, RCMK given, AUTO UMFPACK's choice
    const std::string& r = o.renumbering;
    if (r == "METIS") {
      control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
    } else if (r == "MDA" || r == "AMD") {
      control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
    } else if (r == "RCMK") {
      control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_GIVEN;
    } else if (r != "AUTO") {
      throw LinearSolverError("UMFPACK: RENUM='" + r + "' is not available (METIS, MDA, AMD, RCMK or AUTO)");
    }
  }
  ~UmfpackSolver() override { release(); }
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  std::string_view backendName() const override { return "UMFPACK"; }
  double factorisationFlops() const override { return numeric_ != nullptr ? info_[UMFPACK_FLOPS] : 0.0; }
  std::string orderingUsed() const override {
    if (symbolic_ == nullptr) {
      return "none";
    }
    const auto used = static_cast<int>(info_[UMFPACK_ORDERING_USED]);
    return used == UMFPACK_ORDERING_AMD     ? "AMD"
           : used == UMFPACK_ORDERING_METIS ? "METIS"
           : used == UMFPACK_ORDERING_GIVEN ? "GIVEN"
                                            : "other";
  }

  void analyse(const SparseMatrix& a) override {
    release();
    const SparsePattern& p = a.pattern();
    n_ = p.size;
    if (p.storage == Storage::Full) {
      start_.assign(p.rowStart.begin(), p.rowStart.end());
      index_.assign(p.columns.begin(), p.columns.end());
      source_.clear();
    } else {
      expand(p);
    }
    values_.assign(index_.size(), 0.0);
    std::vector<int> order;
    if (options_.renumbering == "RCMK") {
      order = reverseCuthillMcKee(p);
    }
    const int status =
        umfpack_di_qsymbolic(n_, n_, start_.data(), index_.data(), nullptr,
                             order.empty() ? nullptr : order.data(), &symbolic_, control_, info_);
    if (status != UMFPACK_OK) {
      throw LinearSolverError("UMFPACK: analysis failed (status " + std::to_string(status) + ")");
    }
  }

  void factorise(const SparseMatrix& a) override {
    if (source_.empty()) {
      values_.assign(a.values().begin(), a.values().end());
    } else {
      for (std::size_t k = 0; k < source_.size(); ++k) {
        values_[k] = a.values()[static_cast<std::size_t>(source_[k])];
      }
    }
    if (numeric_ != nullptr) {
      umfpack_di_free_numeric(&numeric_);
    }
    const int status = umfpack_di_numeric(start_.data(), index_.data(), values_.data(), symbolic_, &numeric_,
                                          control_, info_);
    if (status == UMFPACK_WARNING_singular_matrix) {
      throw SingularMatrixError("UMFPACK", nullPivotEquation(-1));
    }
    if (status != UMFPACK_OK) {
      throw LinearSolverError("UMFPACK: factorisation failed (status " + std::to_string(status) + ")");
    }
    if (options_.stopIfSingular) {
      const int eq = nullPivotEquation(options_.nprec);
      if (eq >= 0) {
        throw SingularMatrixError("UMFPACK", eq);
      }
    }
  }

  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override {
    Eigen::VectorXd x(n_), b(n_);
    for (Eigen::Index c = 0; c < rhs.cols(); ++c) {
      b = rhs.col(c);
      const int status = umfpack_di_solve(UMFPACK_At, start_.data(), index_.data(), values_.data(), x.data(),
                                          b.data(), numeric_, control_, info_);
      if (status != UMFPACK_OK) {
        throw LinearSolverError("UMFPACK: solution failed (status " + std::to_string(status) + ")");
      }
      rhs.col(c) = x;
    }
  }

private:
  // Equation of the first null pivot of U (exactly zero when nprec < 0, else relative to
  // 10^-nprec), -1 if none. With P A^T Q = L U the dependent row of our matrix is Q[k].
  int nullPivotEquation(int nprec) {
    std::vector<double> udiag(static_cast<std::size_t>(n_));
    std::vector<int> p(static_cast<std::size_t>(n_)), q(static_cast<std::size_t>(n_));
    int doRecip = 0;
    const int status = umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, p.data(),
                                              q.data(), udiag.data(), &doRecip, nullptr, numeric_);
    if (status != UMFPACK_OK) {
      return -1;
    }
    const Eigen::Map<Eigen::VectorXd> d(udiag.data(), n_);
    int k = -1;
    if (nprec < 0) {
      for (int i = 0; i < n_; ++i) {
        if (d[i] == 0.0) {
          k = i;
          break;
        }
      }
    } else {
      k = firstNullPivot(d, nprec, penaltyRatio_);
    }
    return k < 0 ? -1 : q[static_cast<std::size_t>(k)];
  }

  void expand(const SparsePattern& p) {
    std::vector<int> count(static_cast<std::size_t>(n_) + 1, 0);
    for (int i = 0; i < n_; ++i) {
      for (auto k = p.rowStart[static_cast<std::size_t>(i)]; k < p.rowStart[static_cast<std::size_t>(i) + 1];
           ++k) {
        const int j = p.columns[static_cast<std::size_t>(k)];
        ++count[static_cast<std::size_t>(i) + 1];
        if (j != i) {
          ++count[static_cast<std::size_t>(j) + 1];
        }
      }
    }
    for (int i = 0; i < n_; ++i) {
      count[static_cast<std::size_t>(i) + 1] += count[static_cast<std::size_t>(i)];
    }
    start_ = count;
    index_.assign(static_cast<std::size_t>(start_.back()), 0);
    source_.assign(index_.size(), 0);
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    // rows in increasing order keep each full row sorted: lower part (from earlier rows) first
    for (int i = 0; i < n_; ++i) {
      for (auto k = p.rowStart[static_cast<std::size_t>(i)]; k < p.rowStart[static_cast<std::size_t>(i) + 1];
           ++k) {
        const int j = p.columns[static_cast<std::size_t>(k)];
        const int at = fill[static_cast<std::size_t>(i)]++;
        index_[static_cast<std::size_t>(at)] = j;
        source_[static_cast<std::size_t>(at)] = k;
        if (j != i) {
          const int at2 = fill[static_cast<std::size_t>(j)]++;
          index_[static_cast<std::size_t>(at2)] = i;
          source_[static_cast<std::size_t>(at2)] = k;
        }
      }
    }
  }

  void release() {
    if (numeric_ != nullptr) {
      umfpack_di_free_numeric(&numeric_);
    }
    if (symbolic_ != nullptr) {
      umfpack_di_free_symbolic(&symbolic_);
    }
  }

  SolverOptions options_;
  double control_[UMFPACK_CONTROL];
  double info_[UMFPACK_INFO];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  int n_ = 0;
  std::vector<int> start_, index_;
  std::vector<std::int64_t> source_; // expanded entry -> stored value
  std::vector<double> values_;
};

} // namespace

std::unique_ptr<LinearSolver> makeUmfpack(const SolverOptions& o, MatrixKind k) {
  return std::make_unique<UmfpackSolver>(o, k);
}

} // namespace stella::linalg::detail
