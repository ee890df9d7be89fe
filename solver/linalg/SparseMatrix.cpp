// Sparse pattern construction (node graph expanded to DOFs), matrix operations and the
// element scatter map.

#include "solver/linalg/SparseMatrix.hpp"

#include <algorithm>
#include <stdexcept>

namespace stella::linalg {

std::int64_t SparsePattern::find(int i, int j) const {
  const auto b = columns.begin() + rowStart[static_cast<std::size_t>(i)];
  const auto e = columns.begin() + rowStart[static_cast<std::size_t>(i) + 1];
  const auto it = std::lower_bound(b, e, j);
  return (it != e && *it == j) ? static_cast<std::int64_t>(it - columns.begin()) : -1;
}

void SparseMatrix::add(int i, int j, double v) {
  if (storage() == Storage::Upper && j < i) {
    return;
  }
  const std::int64_t k = pattern_->find(i, j);
  if (k < 0) {
    throw std::out_of_range("SparseMatrix::add: entry not in the pattern");
  }
  values_[static_cast<std::size_t>(k)] += v;
}

Eigen::VectorXd SparseMatrix::multiply(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const SparsePattern& p = *pattern_;
  Eigen::VectorXd y = Eigen::VectorXd::Zero(p.size);
  for (int i = 0; i < p.size; ++i) {
    for (auto k = p.rowStart[static_cast<std::size_t>(i)]; k < p.rowStart[static_cast<std::size_t>(i) + 1];
         ++k) {
      const int j = p.columns[static_cast<std::size_t>(k)];
      const double v = values_[static_cast<std::size_t>(k)];
      y[i] += v * x[j];
      if (p.storage == Storage::Upper && j != i) {
        y[j] += v * x[i];
      }
    }
  }
  return y;
}

Eigen::MatrixXd SparseMatrix::toDense() const {
  const SparsePattern& p = *pattern_;
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(p.size, p.size);
  for (int i = 0; i < p.size; ++i) {
    for (auto k = p.rowStart[static_cast<std::size_t>(i)]; k < p.rowStart[static_cast<std::size_t>(i) + 1];
         ++k) {
      const int j = p.columns[static_cast<std::size_t>(k)];
      d(i, j) = values_[static_cast<std::size_t>(k)];
      if (p.storage == Storage::Upper) {
        d(j, i) = d(i, j);
      }
    }
  }
  return d;
}

SparseMatrix sparseMatrixOf(int n, Storage storage, const std::vector<Eigen::Triplet<double>>& entries) {
  std::vector<Eigen::Triplet<double>> kept;
  kept.reserve(entries.size() + static_cast<std::size_t>(n));
  for (const auto& e : entries) {
    if (storage == Storage::Full || e.col() >= e.row()) {
      kept.push_back(e);
    }
  }
  for (int i = 0; i < n; ++i) {
    kept.emplace_back(i, i, 0.0); // every diagonal entry in the pattern
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> a(n, n);
  a.setFromTriplets(kept.begin(), kept.end()); // sums duplicates, keeps explicit zeros
  auto p = std::make_shared<SparsePattern>();
  p->size = n;
  p->storage = storage;
  p->rowStart.assign(static_cast<std::size_t>(n) + 1, 0);
  p->columns.reserve(static_cast<std::size_t>(a.nonZeros()));
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(a.nonZeros()));
  for (int i = 0; i < n; ++i) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, i); it; ++it) {
      p->columns.push_back(static_cast<int>(it.col()));
      values.push_back(it.value());
    }
    p->rowStart[static_cast<std::size_t>(i) + 1] = static_cast<std::int64_t>(p->columns.size());
  }
  SparseMatrix m(std::move(p));
  m.values() = std::move(values);
  return m;
}

} // namespace stella::linalg
