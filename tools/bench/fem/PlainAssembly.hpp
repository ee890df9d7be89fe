#pragma once
// The plain-array assembly of the benchmarks stella-bench-fem and stella-bench-factor-rate (see
// PlainAssembly.cpp): the kernel timed without the model layer. The run numbers its unknowns with
// DofMap and assembles with StiffnessMatrix (solver/assembly), as stella-bench-system times it.

#include "solver/linalg/SparseMatrix.hpp"

#include <Eigen/Dense>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace stella::bench {

// Every node carries `components` DOFs (node by node), then `multipliers` Lagrange multipliers.
struct PlainNumbering {
  int nodes = 0;
  int components = 3;
  int multipliers = 0;
  int dof(int node, int c) const { return node * components + c; }
  int physicalDofCount() const { return nodes * components; }
  int dofCount() const { return physicalDofCount() + multipliers; }
  // Appends a multiplier; returns its equation.
  int addMultiplier() { return physicalDofCount() + multipliers++; }
};

// Cells as a list of node lists: nodes of cell c are connectivity[offsets[c] .. offsets[c+1]).
struct CellList {
  std::span<const int> connectivity;
  std::span<const std::int64_t> offsets;
  int cellCount() const { return static_cast<int>(offsets.size()) - 1; }
};

// Pattern of the DOFs of `numbering` coupled by the cells, plus `extra` DOF pairs (both (i, j)
// and (j, i) are added), plus every diagonal entry.
std::shared_ptr<const linalg::SparsePattern> buildPattern(const PlainNumbering& numbering,
                                                          const CellList& cells,
                                                          std::span<const std::pair<int, int>> extra,
                                                          linalg::Storage storage);

// Precomputed positions of every cell's element matrix in the pattern: for each cell, each
// local row DOF and each node of the cell, the offset within the row of the first stored column
// of that node's DOF block (16 bits: rows hold at most 65534 entries). Cells carry all physical
// components of their nodes (element DOF order: node by node, component by component).
class ElementScatter {
public:
  ElementScatter(const linalg::SparsePattern& pattern, const PlainNumbering& numbering,
                 const CellList& cells);
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
  const linalg::SparsePattern* pattern_;
  int components_;
  std::vector<std::int64_t> rowStart_;    // per cell into rows_
  std::vector<int> rows_;                 // global DOF of each local DOF
  std::vector<std::uint16_t> offsets_;    // per (local row, node): offset of the block in the row
  std::vector<std::int64_t> offsetStart_; // per cell into offsets_
};

} // namespace stella::bench
