#pragma once
// Sparse matrices in compressed rows (CSR), stored full or as the upper triangle only (for
// symmetric matrices). The run builds its patterns in solver/assembly (StiffnessMatrix from the
// DofMap and the cells, the bordered matrix in SaddleSolver); sparseMatrixOf makes one from entries.

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace stella::linalg {

enum class Storage { Full, Upper }; // Upper: entries (i, j) with j >= i only

struct SparsePattern {
  int size = 0;
  Storage storage = Storage::Full;
  std::vector<std::int64_t> rowStart; // size + 1
  std::vector<int> columns;           // sorted within each row
  std::int64_t nonZeros() const { return rowStart.empty() ? 0 : rowStart.back(); }
  // Position of entry (i, j) in the value array, or -1 if not in the pattern (for Upper storage
  // pass i <= j).
  std::int64_t find(int i, int j) const;
};

class SparseMatrix {
public:
  SparseMatrix() = default;
  explicit SparseMatrix(std::shared_ptr<const SparsePattern> p)
      : pattern_(std::move(p)), values_(static_cast<std::size_t>(pattern_->nonZeros()), 0.0) {}
  const SparsePattern& pattern() const { return *pattern_; }
  std::shared_ptr<const SparsePattern> sharedPattern() const { return pattern_; }
  int size() const { return pattern_->size; }
  Storage storage() const { return pattern_->storage; }
  std::vector<double>& values() { return values_; }
  const std::vector<double>& values() const { return values_; }
  void setZero() { std::fill(values_.begin(), values_.end(), 0.0); }
  // Adds v to entry (i, j); in Upper storage entries below the diagonal are ignored (the
  // symmetric counterpart carries them). Throws if the entry is not in the pattern.
  void add(int i, int j, double v);
  // y = A x (the full matrix, also in Upper storage).
  Eigen::VectorXd multiply(const Eigen::Ref<const Eigen::VectorXd>& x) const;
  Eigen::MatrixXd toDense() const;

private:
  std::shared_ptr<const SparsePattern> pattern_;
  std::vector<double> values_;
};

// The n x n matrix of `entries` (row, column, value; duplicates summed; in Upper storage the
// entries below the diagonal are dropped), every diagonal entry in the pattern (zero if not given).
// Explicit zeros keep their place in the pattern.
SparseMatrix sparseMatrixOf(int n, Storage storage, const std::vector<Eigen::Triplet<double>>& entries);

} // namespace stella::linalg
