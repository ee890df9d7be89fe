// The plain-array assembly of the linear-solver benchmark (stella-bench-fem) and of the cube of
// the factorisation-rate benchmark: every node of the box carries DOFs (node by node, component by
// component), then the Lagrange multipliers; the sparsity pattern from the cells' node graph plus
// the multipliers' couplings; element matrices scattered through a precomputed position map.
// The run numbers and assembles through DofMap / StiffnessMatrix (solver/assembly); this copy
// stays with the benchmarks that time the kernel without the model layer.

#include "tools/bench/fem/PlainAssembly.hpp"

#include <algorithm>
#include <stdexcept>

namespace stella::bench {

using linalg::SparsePattern;
using linalg::Storage;

std::shared_ptr<const SparsePattern> buildPattern(const PlainNumbering& numbering, const CellList& cells,
                                                  std::span<const std::pair<int, int>> extra,
                                                  Storage storage) {
  const int nodes = numbering.nodes;
  const int ncomp = numbering.components;
  const int n = numbering.dofCount();
  // node -> cells
  std::vector<std::int64_t> nodeCellStart(static_cast<std::size_t>(nodes) + 1, 0);
  for (int node : cells.connectivity) {
    ++nodeCellStart[static_cast<std::size_t>(node) + 1];
  }
  for (int a = 0; a < nodes; ++a) {
    nodeCellStart[static_cast<std::size_t>(a) + 1] += nodeCellStart[static_cast<std::size_t>(a)];
  }
  std::vector<int> nodeCells(cells.connectivity.size());
  {
    std::vector<std::int64_t> fill(nodeCellStart.begin(), nodeCellStart.end() - 1);
    for (int c = 0; c < cells.cellCount(); ++c) {
      for (auto k = cells.offsets[static_cast<std::size_t>(c)];
           k < cells.offsets[static_cast<std::size_t>(c) + 1]; ++k) {
        const int node = cells.connectivity[static_cast<std::size_t>(k)];
        nodeCells[static_cast<std::size_t>(fill[static_cast<std::size_t>(node)]++)] = c;
      }
    }
  }
  // extra couplings grouped by row
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(2 * extra.size());
  for (const auto& [i, j] : extra) {
    pairs.emplace_back(i, j);
    pairs.emplace_back(j, i);
  }
  std::sort(pairs.begin(), pairs.end());
  auto pr = pairs.begin();

  auto p = std::make_shared<SparsePattern>();
  p->size = n;
  p->storage = storage;
  p->rowStart.assign(static_cast<std::size_t>(n) + 1, 0);
  p->columns.reserve(static_cast<std::size_t>(n) * 20);
  std::vector<int> mark(static_cast<std::size_t>(nodes), -1);
  std::vector<int> neighbours;
  std::vector<int> row;
  int currentNode = -1;
  for (int r = 0; r < n; ++r) {
    row.clear();
    if (r < numbering.physicalDofCount()) {
      const int a = r / ncomp;
      if (a != currentNode) {
        currentNode = a;
        neighbours.clear();
        for (auto k = nodeCellStart[static_cast<std::size_t>(a)];
             k < nodeCellStart[static_cast<std::size_t>(a) + 1]; ++k) {
          const int c = nodeCells[static_cast<std::size_t>(k)];
          for (auto m = cells.offsets[static_cast<std::size_t>(c)];
               m < cells.offsets[static_cast<std::size_t>(c) + 1]; ++m) {
            const int b = cells.connectivity[static_cast<std::size_t>(m)];
            if (mark[static_cast<std::size_t>(b)] != a) {
              mark[static_cast<std::size_t>(b)] = a;
              neighbours.push_back(numbering.dof(b, 0));
            }
          }
        }
        std::sort(neighbours.begin(), neighbours.end());
      }
      for (int f : neighbours) {
        for (int c = 0; c < ncomp; ++c) {
          row.push_back(f + c);
        }
      }
    }
    row.push_back(r);
    while (pr != pairs.end() && pr->first < r) {
      ++pr;
    }
    for (; pr != pairs.end() && pr->first == r; ++pr) {
      row.push_back(pr->second);
    }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    for (int c : row) {
      if (storage == Storage::Full || c >= r) {
        p->columns.push_back(c);
      }
    }
    p->rowStart[static_cast<std::size_t>(r) + 1] = static_cast<std::int64_t>(p->columns.size());
  }
  p->columns.shrink_to_fit();
  return p;
}

ElementScatter::ElementScatter(const SparsePattern& pattern, const PlainNumbering& numbering,
                               const CellList& cells)
    : pattern_(&pattern), components_(numbering.components) {
  const int nc = components_;
  rowStart_.reserve(static_cast<std::size_t>(cells.cellCount()) + 1);
  rowStart_.push_back(0);
  for (int c = 0; c < cells.cellCount(); ++c) {
    const auto b = cells.offsets[static_cast<std::size_t>(c)];
    const auto e = cells.offsets[static_cast<std::size_t>(c) + 1];
    rowStart_.push_back(rowStart_.back() + (e - b) * nc);
  }
  rows_.resize(static_cast<std::size_t>(rowStart_.back()));
  std::size_t offsetCount = 0;
  for (int c = 0; c < cells.cellCount(); ++c) {
    const auto nn = static_cast<std::size_t>(cells.offsets[static_cast<std::size_t>(c) + 1] -
                                             cells.offsets[static_cast<std::size_t>(c)]);
    offsetCount += nn * nn * static_cast<std::size_t>(nc);
  }
  offsets_.resize(offsetCount);
  offsetStart_.reserve(static_cast<std::size_t>(cells.cellCount()));
  std::size_t o = 0;
  for (int c = 0; c < cells.cellCount(); ++c) {
    offsetStart_.push_back(static_cast<std::int64_t>(o));
    const auto b = cells.offsets[static_cast<std::size_t>(c)];
    const int nn = static_cast<int>(cells.offsets[static_cast<std::size_t>(c) + 1] - b);
    int* rows = rows_.data() + rowStart_[static_cast<std::size_t>(c)];
    for (int a = 0; a < nn; ++a) {
      const int f = numbering.dof(cells.connectivity[static_cast<std::size_t>(b + a)], 0);
      for (int k = 0; k < nc; ++k) {
        rows[a * nc + k] = f + k;
      }
    }
    for (int i = 0; i < nn * nc; ++i) {
      const int r = rows[i];
      const auto rs = pattern.rowStart[static_cast<std::size_t>(r)];
      for (int a = 0; a < nn; ++a) {
        const int f = rows[a * nc];
        int first = f;
        if (pattern.storage == Storage::Upper) {
          first = std::max(f, r);
          if (first > f + nc - 1) {
            offsets_[o++] = notStored;
            continue;
          }
        }
        const std::int64_t k = pattern.find(r, first);
        if (k < 0 || k - rs >= notStored) {
          throw std::logic_error("ElementScatter: cell block missing from the pattern");
        }
        offsets_[o++] = static_cast<std::uint16_t>(k - rs);
      }
    }
  }
}

void ElementScatter::add(int cell, const Eigen::Ref<const Eigen::MatrixXd>& ke,
                         std::vector<double>& values) const {
  const auto rb = static_cast<std::size_t>(rowStart_[static_cast<std::size_t>(cell)]);
  const int ndof = static_cast<int>(rowStart_[static_cast<std::size_t>(cell) + 1] -
                                    rowStart_[static_cast<std::size_t>(cell)]);
  const int nc = components_;
  const int nn = ndof / nc;
  const int* rows = rows_.data() + rb;
  const std::uint16_t* off = offsets_.data() + offsetStart_[static_cast<std::size_t>(cell)];
  const bool upper = pattern_->storage == Storage::Upper;
  for (int i = 0; i < ndof; ++i) {
    const int r = rows[i];
    double* rowValues = values.data() + pattern_->rowStart[static_cast<std::size_t>(r)];
    for (int a = 0; a < nn; ++a) {
      const std::uint16_t o = off[i * nn + a];
      if (o == notStored) {
        continue;
      }
      const int f = rows[a * nc];
      const int first = upper ? std::max(f, r) : f;
      for (int col = first; col < f + nc; ++col) {
        rowValues[o + (col - first)] += ke(i, a * nc + (col - f));
      }
    }
  }
}

} // namespace stella::bench
