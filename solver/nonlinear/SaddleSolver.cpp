// SaddleSolver: the bordered matrix from K, its factorisation and the singularity diagnosis.

#include "solver/nonlinear/SaddleSolver.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>
#include <tuple>

namespace stella {

SaddleSolver::SaddleSolver(const DofMap& dofs, const Mesh& mesh, std::vector<ConstraintRow> rows,
                           std::vector<bool> eliminated)
    : dofs_(dofs), mesh_(mesh), rows_(std::move(rows)), eliminated_(std::move(eliminated)) {}

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
          msg::make("SOLVE_1", {{"describe", dofs_.describe(i, mesh_)}, {"d", d(p)}, {"diag", diag}}));
    }
  }
}

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

double meanDiagonal(const StiffnessMatrix& k) {
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < k.size(); ++i) {
    const double d = std::fabs(k.diagonal(i));
    if (d > 0.0) {
      sum += d;
      ++count;
    }
  }
  return count > 0 ? sum / count : 1.0;
}

// SOLVE_2: the backend failed (a factorisation, or an iterative solve that did not converge).
UserError solverFailure(const linalg::LinearSolverError& e) {
  return UserError(msg::make("SOLVE_2", {{"what", e.what()}}));
}

bool samePattern(const linalg::SparsePattern& a, const linalg::SparsePattern& b) {
  return a.size == b.size && a.storage == b.storage && a.rowStart == b.rowStart && a.columns == b.columns;
}

} // namespace

std::string SaddleSolver::backendName() const {
  return solver_ ? std::string(solver_->backendName()) : std::string("-");
}

std::string SaddleSolver::backendSummary() const {
  return solver_ ? solver_->summary() : std::string();
}

long long SaddleSolver::mumpsInfog(int i) const {
  return solver_ ? solver_->mumpsInfog(i) : 0;
}

void SaddleSolver::chooseCondensedRelations(const std::vector<std::vector<std::pair<int, double>>>& merged) {
  const int n = dofs_.physicalCount();
  removed_ = eliminated_;
  condensed_.clear();
  keptRows_.clear();
  std::vector<int> holders(static_cast<std::size_t>(n), 0);
  for (const auto& terms : merged) {
    for (const auto& [j, c] : terms) {
      ++holders[static_cast<std::size_t>(j)];
    }
  }
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const auto& terms = merged[r];
    bool single = condense_ && terms.size() == 1 && terms[0].second != 0.0 &&
                  holders[static_cast<std::size_t>(terms[0].first)] == 1;
    // a term on an eliminated DOF would move a prescribed value into g: left dualised
    for (const auto& t : rows_[r].terms) {
      single = single && t.first == terms[0].first;
    }
    if (single) {
      condensed_.push_back({static_cast<int>(r), terms[0].first, terms[0].second});
      removed_[static_cast<std::size_t>(terms[0].first)] = true;
    } else {
      keptRows_.push_back(static_cast<int>(r));
    }
  }
}

void SaddleSolver::prepareRelations() {
  if (!dofTermStart_.empty()) {
    return;
  }
  const int n = dofs_.physicalCount();
  std::vector<std::vector<std::pair<int, double>>> merged(rows_.size());
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    std::vector<std::pair<int, double>> terms;
    for (const auto& [j, c] : rows_[r].terms) {
      if (!eliminated_[static_cast<std::size_t>(j)]) {
        terms.emplace_back(j, c);
      }
    }
    std::stable_sort(terms.begin(), terms.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& t : terms) {
      if (!merged[r].empty() && merged[r].back().first == t.first) {
        merged[r].back().second += t.second;
      } else {
        merged[r].push_back(t);
      }
    }
  }
  chooseCondensedRelations(merged);
  rowTerms_.assign(keptRows_.size(), {});
  std::vector<std::tuple<int, int, double>> byDof; // (DOF, kept relation, coefficient)
  for (std::size_t k = 0; k < keptRows_.size(); ++k) {
    rowTerms_[k] = std::move(merged[static_cast<std::size_t>(keptRows_[k])]);
    for (const auto& [j, c] : rowTerms_[k]) {
      byDof.emplace_back(j, static_cast<int>(k), c);
    }
  }
  std::sort(byDof.begin(), byDof.end(), [](const auto& x, const auto& y) {
    return std::tie(std::get<0>(x), std::get<1>(x)) < std::tie(std::get<0>(y), std::get<1>(y));
  });
  dofTermStart_.assign(static_cast<std::size_t>(n) + 1, 0);
  dofTerms_.clear();
  dofTerms_.reserve(byDof.size());
  for (const auto& [j, r, c] : byDof) {
    ++dofTermStart_[static_cast<std::size_t>(j) + 1];
    dofTerms_.emplace_back(r, c);
  }
  for (int i = 0; i < n; ++i) {
    dofTermStart_[static_cast<std::size_t>(i) + 1] += dofTermStart_[static_cast<std::size_t>(i)];
  }
}

template <class Entry, class RowEnd>
void SaddleSolver::walk(const StiffnessMatrix& k, linalg::Storage storage, Entry&& entry,
                        RowEnd&& rowEnd) const {
  const int n = dofs_.physicalCount();
  const int m = static_cast<int>(keptRows_.size());
  const bool upper = storage == linalg::Storage::Upper;
  for (int i = 0; i < n; ++i) {
    if (removed_[static_cast<std::size_t>(i)]) {
      entry(i, scale_);
    } else {
      k.forEachInRow(i, [&](int j, double v) {
        if (!removed_[static_cast<std::size_t>(j)] && (!upper || j >= i)) {
          entry(j, v);
        }
      });
      for (auto t = dofTermStart_[static_cast<std::size_t>(i)];
           t < dofTermStart_[static_cast<std::size_t>(i) + 1]; ++t) {
        const auto& [r, c] = dofTerms_[static_cast<std::size_t>(t)];
        entry(n + r, scale_ * c);
      }
    }
    rowEnd(i);
  }
  for (int r = 0; r < m; ++r) {
    if (!upper) {
      for (const auto& [j, c] : rowTerms_[static_cast<std::size_t>(r)]) {
        entry(j, scale_ * c);
      }
    }
    entry(n + r, 0.0); // keep the diagonal in the pattern
    rowEnd(n + r);
  }
}

bool SaddleSolver::border(const StiffnessMatrix& k, linalg::Storage storage) {
  prepareRelations();
  const int size = dofs_.physicalCount() + static_cast<int>(keptRows_.size());
  if (bordered_.sharedPattern() && borderedFor_ == k.patternId() && bordered_.storage() == storage) {
    double* v = bordered_.values().data();
    std::size_t at = 0;
    walk(
        k, storage, [&](int, double value) { v[at++] = value; }, [](int) {});
    return false;
  }
  auto pattern = std::make_shared<linalg::SparsePattern>();
  pattern->size = size;
  pattern->storage = storage;
  pattern->rowStart.assign(static_cast<std::size_t>(size) + 1, 0);
  std::vector<double> values;
  walk(
      k, storage,
      [&](int j, double value) {
        pattern->columns.push_back(j);
        values.push_back(value);
      },
      [&](int row) {
        pattern->rowStart[static_cast<std::size_t>(row) + 1] =
            static_cast<std::int64_t>(pattern->columns.size());
      });
  borderedFor_ = k.patternId();
  const bool changed = !bordered_.sharedPattern() || !samePattern(*pattern, bordered_.pattern());
  bordered_ = linalg::SparseMatrix(changed ? std::shared_ptr<const linalg::SparsePattern>(std::move(pattern))
                                           : bordered_.sharedPattern());
  bordered_.values() = std::move(values);
  return changed;
}

void SaddleSolver::extractEliminatedColumns(const StiffnessMatrix& k) {
  const int n = dofs_.physicalCount();
  anyEliminated_ = std::find(removed_.begin(), removed_.end(), true) != removed_.end();
  if (!anyEliminated_) {
    eliminatedColumns_ = Eigen::SparseMatrix<double>();
    condensedRows_ = Eigen::SparseMatrix<double>();
    return;
  }
  std::vector<bool> condensed(static_cast<std::size_t>(n), false);
  for (const auto& c : condensed_) {
    condensed[static_cast<std::size_t>(c.dof)] = true;
  }
  const bool upper = k.storage() == linalg::Storage::Upper;
  std::vector<Eigen::Triplet<double>> t;
  std::vector<Eigen::Triplet<double>> rowsOfK;
  for (int i = 0; i < n; ++i) {
    const bool ei = removed_[static_cast<std::size_t>(i)];
    const bool ci = condensed[static_cast<std::size_t>(i)];
    k.forEachInRow(i, [&](int j, double v) {
      if (removed_[static_cast<std::size_t>(j)]) {
        t.emplace_back(i, j, v);
      }
      if (upper && ei && j != i) {
        t.emplace_back(j, i, v);
      }
      if (ci) {
        rowsOfK.emplace_back(i, j, v);
      }
      if (upper && condensed[static_cast<std::size_t>(j)] && j != i) {
        rowsOfK.emplace_back(j, i, v);
      }
    });
  }
  eliminatedColumns_.resize(n, n);
  eliminatedColumns_.setFromTriplets(t.begin(), t.end());
  condensedRows_.resize(n, n);
  condensedRows_.setFromTriplets(rowsOfK.begin(), rowsOfK.end());
}

void SaddleSolver::factorize(const Eigen::SparseMatrix<double>& k, bool checkSingular, bool symmetric) {
  const linalg::Storage storage = symmetric ? linalg::Storage::Upper : linalg::Storage::Full;
  const StiffnessMatrix matrix(k, storage);
  if (checkSingular) {
    scale_ = meanDiagonal(matrix);
    checkSingularity(k);
  }
  factorize(matrix, symmetric);
}

// Per physical equation, its node's coordinate along the equation's component (the near-null
// space of METHODE='PETSC''s multigrids).
std::vector<double> SaddleSolver::equationCoordinates() const {
  const int n = dofs_.physicalCount();
  const int d = dofs_.components();
  std::vector<double> out(static_cast<std::size_t>(n));
  const std::vector<double>& xyz = mesh_.coordinates();
  for (int e = 0; e < n; ++e) {
    out[static_cast<std::size_t>(e)] =
        xyz[3 * static_cast<std::size_t>(dofs_.node(e)) + static_cast<std::size_t>(e % d)];
  }
  return out;
}

void SaddleSolver::factorize(const StiffnessMatrix& k, bool symmetric) {
  const auto start = Clock::now();
  prepareRelations();
  const int m = static_cast<int>(keptRows_.size());
  const linalg::MatrixKind kind = !symmetric ? linalg::MatrixKind::Unsymmetric
                                  : m > 0    ? linalg::MatrixKind::SymmetricIndefinite
                                             : linalg::MatrixKind::SymmetricPositiveDefinite;
  const linalg::Storage storage = linalg::storageFor(kind);
  if (storage == linalg::Storage::Full && k.storage() == linalg::Storage::Upper) {
    throw std::logic_error("SaddleSolver: an unsymmetric factorisation needs K stored in full");
  }
  scale_ = meanDiagonal(k);
  border(k, storage);
  extractEliminatedColumns(k);
  timings_.bordering += secondsSince(start);
  try {
    if (!solver_ || solver_->kind() != kind) {
      solver_ = linalg::makeLinearSolver(options_, kind);
      if (options_.method == linalg::SolverMethod::Petsc) {
        solver_->setNodeCoordinates(dofs_.components(), equationCoordinates());
      }
      analysed_.reset();
      factorisedValues_.clear();
    }
    if (analysed_ != bordered_.sharedPattern()) {
      const auto t = Clock::now();
      solver_->analyse(bordered_);
      analysed_ = bordered_.sharedPattern();
      factorisedValues_.clear();
      timings_.analysis += secondsSince(t);
      ++timings_.analyses;
    }
    if (keepUnchanged_ && factorisedValues_ == bordered_.values()) {
      // The values already factorised (elastic bodies under dual contact, whose tangent does not
      // change between iterations): the factors are reused, the solution is the same.
      ++reusedFactorizations_;
      return;
    }
    factorisedValues_.clear();
    const auto t = Clock::now();
    solver_->setPenaltyRatio(penaltyRatio_);
    solver_->factorise(bordered_);
    timings_.factorisation += secondsSince(t);
    if (keepUnchanged_) {
      factorisedValues_.assign(bordered_.values().begin(), bordered_.values().end());
    }
  } catch (const linalg::SingularMatrixError& e) {
    // Only now the (costly) diagnosis that names the free node and component.
    checkSingularity(k.toEigen());
    const int n = dofs_.physicalCount();
    const int eq = e.equation() >= n && e.equation() < n + static_cast<int>(keptRows_.size())
                       ? n + keptRows_[static_cast<std::size_t>(e.equation() - n)]
                       : e.equation();
    throw UserError(msg::make(
        "SOLVE_1.2", {{"backend", e.backend()},
                      {"eq", eq >= 0 && eq < dofs_.size() ? " at " + dofs_.describe(eq, mesh_) : ""}}));
  } catch (const linalg::LinearSolverError& e) {
    throw solverFailure(e);
  }
  ++factorizations_;
}

void SaddleSolver::solve(const Eigen::VectorXd& r, const Eigen::VectorXd& g,
                         const Eigen::VectorXd& prescribed, Eigen::VectorXd& du, Eigen::VectorXd& dlambda) {
  const int n = dofs_.physicalCount();
  const int m = static_cast<int>(keptRows_.size());
  Eigen::VectorXd b(n + m);
  b.head(n) = r;
  for (int k = 0; k < m; ++k) {
    b(n + k) = scale_ * g(keptRows_[static_cast<std::size_t>(k)]);
  }
  // Move the prescribed increments of eliminated DOFs to the right-hand side.
  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    if (eliminated_[static_cast<std::size_t>(i)]) {
      p(i) = prescribed(i);
    }
  }
  for (const auto& c : condensed_) {
    p(c.dof) = g(c.row) / c.coefficient;
  }
  if (anyEliminated_ && n > 0 && p.cwiseAbs().maxCoeff() != 0.0) {
    b.head(n) -= eliminatedColumns_ * p;
    for (int k = 0; k < m; ++k) {
      for (const auto& [j, c] :
           rows_[static_cast<std::size_t>(keptRows_[static_cast<std::size_t>(k)])].terms) {
        if (removed_[static_cast<std::size_t>(j)]) {
          b(n + k) -= scale_ * c * p(j);
        }
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    if (removed_[static_cast<std::size_t>(i)]) {
      b(i) = scale_ * p(i);
    }
  }
  Eigen::VectorXd x = b;
  solveBordered(Eigen::Map<Eigen::MatrixXd>(x.data(), x.size(), 1));
  du = x.head(n);
  dlambda.resize(static_cast<Eigen::Index>(rows_.size()));
  for (int k = 0; k < m; ++k) {
    dlambda(keptRows_[static_cast<std::size_t>(k)]) = scale_ * x(n + k);
  }
  if (!condensed_.empty()) {
    for (const auto& c : condensed_) {
      du(c.dof) = p(c.dof);
    }
    // row j of the first block: K_j du + c lambda = r_j
    const Eigen::VectorXd kdu = condensedRows_ * du;
    for (const auto& c : condensed_) {
      dlambda(c.row) = (r(c.dof) - kdu(c.dof)) / c.coefficient;
    }
  }
}

void SaddleSolver::solveHomogeneous(Eigen::Ref<Eigen::MatrixXd> rhs) {
  const Eigen::Index n = dofs_.physicalCount();
  const Eigen::Index m = static_cast<Eigen::Index>(keptRows_.size());
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n + m, rhs.cols());
  x.topRows(n) = rhs;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (removed_[static_cast<std::size_t>(i)]) {
      x.row(i).setZero();
    }
  }
  solveBordered(x);
  rhs = x.topRows(n);
}

void SaddleSolver::solveBordered(Eigen::Ref<Eigen::MatrixXd> x) {
  const auto start = Clock::now();
  try {
    solver_->solve(x);
  } catch (const linalg::LinearSolverError& e) {
    // an iterative solve that did not converge: the user's SOLVEUR, not an internal error
    throw solverFailure(e);
  }
  timings_.solve += secondsSince(start);
  if (!x.allFinite()) {
    throw UserError(msg::make("SOLVE_3"));
  }
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
