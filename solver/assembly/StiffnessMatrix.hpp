#pragma once
// The physical block K of the tangent stiffness, assembled in place in compressed rows (CSR):
// the pattern (every pair of DOFs coupled by a volume cell, and every diagonal entry) is computed
// once per model and DOF numbering, and element matrices are added through a precomputed map of
// their positions (no search, no triplets). Entries outside that pattern (penalised contact
// couplings, whose pairs change during the analysis) go to a second, small pattern that only
// grows: a pair once seen keeps its place (as a zero when the link is open), so the
// factorisation's symbolic analysis is redone only when a new pair appears (patternId()).
//
// Symmetric tangents keep the upper triangle only (j >= i); unsymmetric ones both.

#include "solver/assembly/DofMap.hpp"
#include "solver/linalg/SparseMatrix.hpp"
#include "solver/mesh/Mesh.hpp"

#include <Eigen/Sparse>
#include <cstdint>
#include <span>
#include <vector>

namespace stella {

class StiffnessMatrix {
public:
  // Pattern of the DOFs coupled by `cells` (the volume cells in the assembler's order; every
  // node of them carries DOFs) plus every diagonal entry of the `dofs.physicalCount()` DOFs.
  StiffnessMatrix(const DofMap& dofs, const Mesh& mesh, std::span<const CellId> cells,
                  linalg::Storage storage);
  // The pattern and values of a given matrix (no cell map; addCell unavailable).
  StiffnessMatrix(const Eigen::SparseMatrix<double>& k, linalg::Storage storage);

  linalg::Storage storage() const { return cells_.storage(); }
  int size() const { return cells_.size(); }
  // Identifies the current pattern (cell part and extra part): it changes when the extra part grows.
  std::uint64_t patternId() const { return patternId_; }

  void setZero();
  // Adds the element matrix of the cell at `index` in the constructor's cell list (DOF order:
  // node by node, component by component). In upper storage only its upper part is read.
  void addCell(std::size_t index, const Eigen::MatrixXd& ke);
  // Adds v to entry (i, j) (in upper storage, entries with j < i are skipped: the symmetric
  // counterpart carries them). Entries outside the pattern extend the extra part.
  void add(int i, int j, double v);
  void add(const std::vector<Eigen::Triplet<double>>& entries);
  // Adds every entry of `other` (same size; an upper-stored one counts for both triangles).
  void add(const StiffnessMatrix& other);

  // Calls f(column, value) for the stored entries of row i in increasing column order (cell and
  // extra parts merged).
  template <class F> void forEachInRow(int i, F&& f) const;

  // K(i, i).
  double diagonal(int i) const;
  // The whole matrix (both triangles) as an Eigen matrix, for diagnostics and tests.
  Eigen::SparseMatrix<double> toEigen() const;
  // Bytes held by the pattern, the values and the cell map.
  std::size_t memoryBytes() const;

private:
  void accumulate(int i, int j, double v); // into pending_ when outside both patterns
  void flushPending();
  void buildCellMap(const DofMap& dofs, const Mesh& mesh, std::span<const CellId> cells);

  linalg::SparseMatrix cells_; // the pattern coupled by the cells, with every diagonal entry
  linalg::SparseMatrix extra_; // the entries outside it (empty pattern when none)
  std::vector<Eigen::Triplet<double>> pending_;
  std::vector<std::int64_t> diagonal_; // position of (i, i) in cells_
  std::uint64_t patternId_ = 0;
  // Cell map: per cell, its nodes' first DOFs and, per (local row, node), the offset in the row
  // of the first stored column of that node's block (notStored when none is).
  int components_ = 0;
  std::vector<std::int64_t> cellStart_; // per cell into cellFirstDof_
  std::vector<int> cellFirstDof_;
  std::vector<std::int64_t> offsetStart_; // per cell into offsets_
  std::vector<std::uint16_t> offsets_;
  static constexpr std::uint16_t notStored = 0xFFFF;
};

template <class F> void StiffnessMatrix::forEachInRow(int i, F&& f) const {
  const linalg::SparsePattern& a = cells_.pattern();
  const auto& av = cells_.values();
  auto ka = a.rowStart[static_cast<std::size_t>(i)];
  const auto ea = a.rowStart[static_cast<std::size_t>(i) + 1];
  if (extra_.pattern().nonZeros() == 0) {
    for (; ka < ea; ++ka) {
      f(a.columns[static_cast<std::size_t>(ka)], av[static_cast<std::size_t>(ka)]);
    }
    return;
  }
  const linalg::SparsePattern& b = extra_.pattern();
  const auto& bv = extra_.values();
  auto kb = b.rowStart[static_cast<std::size_t>(i)];
  const auto eb = b.rowStart[static_cast<std::size_t>(i) + 1];
  while (ka < ea || kb < eb) { // the two parts never share an entry
    if (kb == eb ||
        (ka < ea && a.columns[static_cast<std::size_t>(ka)] < b.columns[static_cast<std::size_t>(kb)])) {
      f(a.columns[static_cast<std::size_t>(ka)], av[static_cast<std::size_t>(ka)]);
      ++ka;
    } else {
      f(b.columns[static_cast<std::size_t>(kb)], bv[static_cast<std::size_t>(kb)]);
      ++kb;
    }
  }
}

} // namespace stella
