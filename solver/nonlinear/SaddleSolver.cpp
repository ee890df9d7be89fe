// SaddleSolver: assembly of the bordered matrix, LU factorisation and the singularity check.

#include "solver/nonlinear/SaddleSolver.hpp"

#include "interpreter/Diagnostics.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <fmt/format.h>

namespace stella {

SaddleSolver::SaddleSolver(const DofMap& dofs, const Mesh& mesh, std::vector<ConstraintRow> rows,
                           std::vector<bool> eliminated)
    : dofs_(dofs), mesh_(mesh), rows_(std::move(rows)), eliminated_(std::move(eliminated)) {}

namespace {

double meanDiagonal(const Eigen::SparseMatrix<double>& k) {
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < k.rows(); ++i) {
    const double d = std::fabs(k.coeff(i, i));
    if (d > 0.0) {
      sum += d;
      ++count;
    }
  }
  return count > 0 ? sum / count : 1.0;
}

} // namespace

void SaddleSolver::checkSingularity(const Eigen::SparseMatrix<double>& k) const {
  const int n = static_cast<int>(k.rows());
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(k.nonZeros()));
  for (int j = 0; j < k.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it) {
      const auto i = static_cast<std::size_t>(it.row());
      if (!eliminated_[i] && !eliminated_[static_cast<std::size_t>(j)]) {
        t.emplace_back(it.row(), j, it.value());
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    if (eliminated_[static_cast<std::size_t>(i)]) {
      t.emplace_back(i, i, scale_);
    }
  }
  for (const auto& row : rows_) {
    for (const auto& [i, a] : row.terms) {
      for (const auto& [j, b] : row.terms) {
        if (!eliminated_[static_cast<std::size_t>(i)] && !eliminated_[static_cast<std::size_t>(j)]) {
          t.emplace_back(i, j, scale_ * a * b);
        }
      }
    }
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(a);
  const Eigen::VectorXd d = ldlt.vectorD();
  const auto& pinv = ldlt.permutationPinv().indices();
  for (int p = 0; p < n; ++p) {
    const int i = pinv(p);
    const double diag = a.coeff(i, i);
    if (!(std::fabs(d(p)) > 1.0e-8 * std::fabs(diag)) || diag == 0.0) {
      throw UserError(
          Diagnostic::fatal(
              "SOLVE_1",
              fmt::format("the stiffness matrix is singular: {} is free (nothing holds it, a "
                          "rigid-body motion or a mechanism; pivot {:.3g} for a diagonal of {:.3g})",
                          dofs_.describe(i, mesh_), d(p), diag))
              .withNote("block this motion with DDL_IMPO (AFFE_CHAR_MECA) or MECA_IMPO (AFFE_CHAR_CINE), or "
                        "hold the body with springs (MODELISATION='DIS_T' or '2D_DIS_T' on POI1 cells with "
                        "AFFE_CARA_ELEM DISCRET K_T_D_N), as §4.4.2 of the notice explains"));
    }
  }
}

namespace {

// The bordered matrix in CSR for the facade (upper triangle when symmetric).
linalg::SparseMatrix toCsr(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, linalg::Storage storage,
                           std::shared_ptr<const linalg::SparsePattern>& cached) {
  auto pattern = std::make_shared<linalg::SparsePattern>();
  pattern->size = static_cast<int>(a.rows());
  pattern->storage = storage;
  pattern->rowStart.assign(static_cast<std::size_t>(a.rows()) + 1, 0);
  std::vector<double> values;
  for (int i = 0; i < a.outerSize(); ++i) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, i); it; ++it) {
      if (storage == linalg::Storage::Upper && it.col() < i) {
        continue;
      }
      pattern->columns.push_back(static_cast<int>(it.col()));
      values.push_back(it.value());
    }
    pattern->rowStart[static_cast<std::size_t>(i) + 1] = static_cast<std::int64_t>(pattern->columns.size());
  }
  if (cached && cached->storage == storage && cached->rowStart == pattern->rowStart &&
      cached->columns == pattern->columns) {
    pattern.reset();
  } else {
    cached = pattern;
  }
  linalg::SparseMatrix m(cached);
  m.values() = std::move(values);
  return m;
}

} // namespace

std::string SaddleSolver::backendName() const {
  return solver_ ? std::string(solver_->backendName()) : std::string("-");
}

void SaddleSolver::factorize(const Eigen::SparseMatrix<double>& k, bool checkSingular, bool symmetric) {
  k_ = k;
  scale_ = meanDiagonal(k);
  if (checkSingular) {
    checkSingularity(k);
  }
  const int n = dofs_.physicalCount();
  const int m = static_cast<int>(rows_.size());
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(k.nonZeros()) + 2 * rows_.size() + static_cast<std::size_t>(n));
  for (int j = 0; j < k.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it) {
      if (!eliminated_[static_cast<std::size_t>(it.row())] && !eliminated_[static_cast<std::size_t>(j)]) {
        t.emplace_back(it.row(), j, it.value());
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    if (eliminated_[static_cast<std::size_t>(i)]) {
      t.emplace_back(i, i, scale_);
    }
  }
  for (int r = 0; r < m; ++r) {
    for (const auto& [j, c] : rows_[static_cast<std::size_t>(r)].terms) {
      if (!eliminated_[static_cast<std::size_t>(j)]) {
        t.emplace_back(n + r, j, scale_ * c);
        t.emplace_back(j, n + r, scale_ * c);
      }
    }
    t.emplace_back(n + r, n + r, 0.0); // keep the diagonal in the pattern
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> a(n + m, n + m);
  a.setFromTriplets(t.begin(), t.end());
  const linalg::MatrixKind kind = !symmetric ? linalg::MatrixKind::Unsymmetric
                                  : m > 0    ? linalg::MatrixKind::SymmetricIndefinite
                                             : linalg::MatrixKind::SymmetricPositiveDefinite;
  const auto previous = pattern_;
  linalg::SparseMatrix csr = toCsr(a, linalg::storageFor(kind), pattern_);
  try {
    if (!solver_ || solver_->kind() != kind) {
      solver_ = linalg::makeLinearSolver(options_, kind);
      solver_->analyse(csr);
    } else if (pattern_ != previous) {
      solver_->analyse(csr);
    }
    solver_->factorise(csr);
  } catch (const linalg::SingularMatrixError& e) {
    checkSingularity(k);
    const int eq = e.equation();
    throw UserError(
        Diagnostic::fatal(
            "SOLVE_1", fmt::format("the stiffness matrix is singular ({} found a null pivot{})", e.backend(),
                                   eq >= 0 && eq < dofs_.size() ? " at " + dofs_.describe(eq, mesh_) : ""))
            .withNote("block the free motions with DDL_IMPO or AFFE_CHAR_CINE, or hold the body with DIS_T "
                      "springs (§4.4.2 of the notice); check that no linear relation repeats another"));
  } catch (const linalg::LinearSolverError& e) {
    throw UserError(Diagnostic::fatal("SOLVE_2", fmt::format("the linear solver failed: {}", e.what()))
                        .withNote("try METHODE='MUMPS' (the default) in SOLVEUR"));
  }
  ++factorizations_;
}

void SaddleSolver::solve(const Eigen::VectorXd& r, const Eigen::VectorXd& g,
                         const Eigen::VectorXd& prescribed, Eigen::VectorXd& du, Eigen::VectorXd& dlambda) {
  const int n = dofs_.physicalCount();
  const int m = static_cast<int>(rows_.size());
  Eigen::VectorXd b(n + m);
  b.head(n) = r;
  b.tail(m) = scale_ * g;
  // Move the prescribed increments of eliminated DOFs to the right-hand side.
  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (eliminated_[static_cast<std::size_t>(i)]) {
      p(i) = prescribed(i);
      any = any || prescribed(i) != 0.0;
    }
  }
  if (any) {
    b.head(n) -= k_ * p;
    for (int rr = 0; rr < m; ++rr) {
      for (const auto& [j, c] : rows_[static_cast<std::size_t>(rr)].terms) {
        if (eliminated_[static_cast<std::size_t>(j)]) {
          b(n + rr) -= scale_ * c * p(j);
        }
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    if (eliminated_[static_cast<std::size_t>(i)]) {
      b(i) = scale_ * p(i);
    }
  }
  Eigen::VectorXd x = b;
  Eigen::Map<Eigen::MatrixXd> column(x.data(), x.size(), 1);
  solver_->solve(column);
  if (!x.allFinite()) {
    throw UserError(Diagnostic::fatal("SOLVE_3", "the linear solve produced non-finite values")
                        .withNote("the system is probably singular or badly conditioned: check the boundary "
                                  "conditions and the material parameters"));
  }
  du = x.head(n);
  dlambda = scale_ * x.tail(m);
}

Eigen::VectorXd SaddleSolver::transposeTimes(const Eigen::VectorXd& lambda) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(dofs_.physicalCount());
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    for (const auto& [j, c] : rows_[r].terms) {
      out(j) += c * lambda(static_cast<Eigen::Index>(r));
    }
  }
  return out;
}

Eigen::VectorXd SaddleSolver::times(const Eigen::VectorXd& u) const {
  Eigen::VectorXd out(static_cast<Eigen::Index>(rows_.size()));
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    double s = 0.0;
    for (const auto& [j, c] : rows_[r].terms) {
      s += c * u(j);
    }
    out(static_cast<Eigen::Index>(r)) = s;
  }
  return out;
}

} // namespace stella
