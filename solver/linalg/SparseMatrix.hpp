#pragma once
// Sparse matrices in compressed rows (CSR), stored full or as the upper triangle only (for
// symmetric matrices). The pattern is built once from the cells' connectivity (through a node
// graph, then expanded to DOFs) plus extra couplings (Lagrange multipliers); element matrices
// are then scattered through a precomputed cell -> position map, without any search.

#include "solver/linalg/DofNumbering.hpp"

#include <Eigen/Dense>
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

// Cells as a list of node lists: nodes of cell c are connectivity[offsets[c] .. offsets[c+1]).
struct CellList {
  std::span<const int> connectivity;
  std::span<const std::int64_t> offsets;
  int cellCount() const { return static_cast<int>(offsets.size()) - 1; }
};

// Pattern of the DOFs of `numbering` coupled by the cells, plus `extra` DOF pairs (both (i, j)
// and (j, i) are added), plus every diagonal entry.
std::shared_ptr<const SparsePattern> buildPattern(const DofNumbering& numbering, const CellList& cells,
                                                  std::span<const std::pair<int, int>> extra,
                                                  Storage storage);

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

// Precomputed positions of every cell's element matrix in the pattern: for each cell, each
// local row DOF and each node of the cell, the offset within the row of the first stored column
// of that node's DOF block (16 bits: rows hold at most 65534 entries). Cells carry all physical
// components of their nodes (element DOF order: node by node, component by component).
class ElementScatter {
public:
  ElementScatter(const SparsePattern& pattern, const DofNumbering& numbering, const CellList& cells);
  // values += ke (nodes*components square) for `cell`.
  void add(int cell, const Eigen::Ref<const Eigen::MatrixXd>& ke, std::vector<double>& values) const;
  // Global DOFs of a cell's local DOFs.
  std::span<const int> dofs(int cell) const {
    const auto b = static_cast<std::size_t>(rowStart_[static_cast<std::size_t>(cell)]);
    const auto e = static_cast<std::size_t>(rowStart_[static_cast<std::size_t>(cell) + 1]);
    return std::span<const int>(rows_).subspan(b, e - b);
  }
  std::size_t memoryBytes() const {
    return offsets_.capacity() * sizeof(std::uint16_t) + rows_.capacity() * sizeof(int) +
           (rowStart_.capacity() + offsetStart_.capacity()) * sizeof(std::int64_t);
  }

private:
  static constexpr std::uint16_t notStored = 0xFFFF;
  const SparsePattern* pattern_;
  int components_;
  std::vector<std::int64_t> rowStart_;    // per cell into rows_
  std::vector<int> rows_;                 // global DOF of each local DOF
  std::vector<std::uint16_t> offsets_;    // per (local row, node): offset of the block in the row
  std::vector<std::int64_t> offsetStart_; // per cell into offsets_
};

} // namespace stella::linalg
