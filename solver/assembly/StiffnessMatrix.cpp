// StiffnessMatrix: the cell pattern, the map of element matrices into it, and the growing extra
// pattern of couplings outside the cells.

#include "solver/assembly/StiffnessMatrix.hpp"

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace stella {

namespace {

std::uint64_t newPatternId() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

std::shared_ptr<const linalg::SparsePattern> emptyPattern(int n, linalg::Storage storage) {
  auto p = std::make_shared<linalg::SparsePattern>();
  p->size = n;
  p->storage = storage;
  p->rowStart.assign(static_cast<std::size_t>(n) + 1, 0);
  return p;
}

// Pattern of sorted (i, j) keys (no duplicates) of an n x n matrix.
std::shared_ptr<const linalg::SparsePattern> patternOf(int n, linalg::Storage storage,
                                                       const std::vector<std::pair<int, int>>& keys) {
  auto p = std::make_shared<linalg::SparsePattern>();
  p->size = n;
  p->storage = storage;
  p->rowStart.assign(static_cast<std::size_t>(n) + 1, 0);
  p->columns.reserve(keys.size());
  for (const auto& [i, j] : keys) {
    ++p->rowStart[static_cast<std::size_t>(i) + 1];
    p->columns.push_back(j);
  }
  for (int i = 0; i < n; ++i) {
    p->rowStart[static_cast<std::size_t>(i) + 1] += p->rowStart[static_cast<std::size_t>(i)];
  }
  return p;
}

} // namespace

StiffnessMatrix::StiffnessMatrix(const DofMap& dofs, const Mesh& mesh, std::span<const CellId> cells,
                                 linalg::Storage storage)
    : components_(dofs.components()) {
  const int n = dofs.physicalCount();
  const int nc = components_;
  const int blocks = n / nc;
  auto blockOf = [&](NodeId node) {
    const int f = dofs.dof(node, 0);
    if (f < 0) {
      throw std::logic_error("StiffnessMatrix: a node of a volume cell carries no DOF");
    }
    return f / nc;
  };
  // DOF block (node) -> cells
  std::vector<std::int64_t> blockCellStart(static_cast<std::size_t>(blocks) + 1, 0);
  for (CellId c : cells) {
    for (NodeId node : mesh.cellNodes(c)) {
      ++blockCellStart[static_cast<std::size_t>(blockOf(node)) + 1];
    }
  }
  for (int b = 0; b < blocks; ++b) {
    blockCellStart[static_cast<std::size_t>(b) + 1] += blockCellStart[static_cast<std::size_t>(b)];
  }
  std::vector<std::size_t> blockCells(static_cast<std::size_t>(blockCellStart.back()));
  {
    std::vector<std::int64_t> fill(blockCellStart.begin(), blockCellStart.end() - 1);
    for (std::size_t k = 0; k < cells.size(); ++k) {
      for (NodeId node : mesh.cellNodes(cells[k])) {
        blockCells[static_cast<std::size_t>(fill[static_cast<std::size_t>(blockOf(node))]++)] = k;
      }
    }
  }
  auto p = std::make_shared<linalg::SparsePattern>();
  p->size = n;
  p->storage = storage;
  p->rowStart.assign(static_cast<std::size_t>(n) + 1, 0);
  std::vector<int> mark(static_cast<std::size_t>(blocks), -1);
  std::vector<int> neighbours;
  for (int b = 0; b < blocks; ++b) {
    neighbours.clear();
    mark[static_cast<std::size_t>(b)] = b;
    neighbours.push_back(b);
    for (auto k = blockCellStart[static_cast<std::size_t>(b)];
         k < blockCellStart[static_cast<std::size_t>(b) + 1]; ++k) {
      for (NodeId node : mesh.cellNodes(cells[blockCells[static_cast<std::size_t>(k)]])) {
        const int nb = blockOf(node);
        if (mark[static_cast<std::size_t>(nb)] != b) {
          mark[static_cast<std::size_t>(nb)] = b;
          neighbours.push_back(nb);
        }
      }
    }
    std::sort(neighbours.begin(), neighbours.end());
    for (int k = 0; k < nc; ++k) {
      const int r = b * nc + k;
      for (int nb : neighbours) {
        for (int c = 0; c < nc; ++c) {
          const int col = nb * nc + c;
          if (storage == linalg::Storage::Full || col >= r) {
            p->columns.push_back(col);
          }
        }
      }
      p->rowStart[static_cast<std::size_t>(r) + 1] = static_cast<std::int64_t>(p->columns.size());
    }
  }
  p->columns.shrink_to_fit();
  diagonal_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    diagonal_[static_cast<std::size_t>(i)] = p->find(i, i);
  }
  cells_ = linalg::SparseMatrix(p);
  extra_ = linalg::SparseMatrix(emptyPattern(n, storage));
  patternId_ = newPatternId();
  buildCellMap(dofs, mesh, cells);
}

StiffnessMatrix::StiffnessMatrix(const Eigen::SparseMatrix<double>& k, linalg::Storage storage) {
  const int n = static_cast<int>(k.rows());
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(k.nonZeros()));
  for (int j = 0; j < k.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(k, j); it; ++it) {
      t.emplace_back(static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
    }
  }
  cells_ = linalg::sparseMatrixOf(n, storage, t);
  diagonal_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    diagonal_[static_cast<std::size_t>(i)] = cells_.pattern().find(i, i);
  }
  extra_ = linalg::SparseMatrix(emptyPattern(n, storage));
  patternId_ = newPatternId();
}

void StiffnessMatrix::buildCellMap(const DofMap& dofs, const Mesh& mesh, std::span<const CellId> cells) {
  const int nc = components_;
  const linalg::SparsePattern& p = cells_.pattern();
  const bool upper = p.storage == linalg::Storage::Upper;
  cellStart_.assign(1, 0);
  cellStart_.reserve(cells.size() + 1);
  offsetStart_.reserve(cells.size() + 1);
  for (CellId c : cells) {
    const auto nodes = mesh.cellNodes(c);
    const auto nn = static_cast<std::int64_t>(nodes.size());
    cellStart_.push_back(cellStart_.back() + nn);
    for (NodeId node : nodes) {
      cellFirstDof_.push_back(dofs.dof(node, 0));
    }
  }
  offsetStart_.assign(1, 0);
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const auto nn = cellStart_[k + 1] - cellStart_[k];
    offsetStart_.push_back(offsetStart_.back() + nn * nc * nn);
  }
  offsets_.resize(static_cast<std::size_t>(offsetStart_.back()));
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const int* first = cellFirstDof_.data() + cellStart_[k];
    const int nn = static_cast<int>(cellStart_[k + 1] - cellStart_[k]);
    std::uint16_t* off = offsets_.data() + offsetStart_[k];
    for (int a = 0; a < nn; ++a) {
      for (int comp = 0; comp < nc; ++comp) {
        const int r = first[a] + comp;
        const auto rs = p.rowStart[static_cast<std::size_t>(r)];
        for (int b = 0; b < nn; ++b) {
          const int f = first[b];
          const int c0 = upper ? std::max(f, r) : f;
          std::uint16_t& o = off[(a * nc + comp) * nn + b];
          if (c0 > f + nc - 1) {
            o = notStored;
            continue;
          }
          const std::int64_t at = p.find(r, c0);
          if (at < 0 || at - rs >= notStored) {
            throw std::logic_error("StiffnessMatrix: a cell block is missing from the pattern");
          }
          o = static_cast<std::uint16_t>(at - rs);
        }
      }
    }
  }
}

void StiffnessMatrix::setZero() {
  cells_.setZero();
  extra_.setZero();
}

void StiffnessMatrix::addCell(std::size_t index, const Eigen::MatrixXd& ke) {
  const int nc = components_;
  const int* first = cellFirstDof_.data() + cellStart_[index];
  const int nn = static_cast<int>(cellStart_[index + 1] - cellStart_[index]);
  const std::uint16_t* off = offsets_.data() + offsetStart_[index];
  const auto& rowStart = cells_.pattern().rowStart;
  double* values = cells_.values().data();
  const bool upper = storage() == linalg::Storage::Upper;
  for (int a = 0; a < nn; ++a) {
    for (int comp = 0; comp < nc; ++comp) {
      const int i = a * nc + comp;
      const int r = first[a] + comp;
      double* row = values + rowStart[static_cast<std::size_t>(r)];
      for (int b = 0; b < nn; ++b) {
        const std::uint16_t o = off[i * nn + b];
        if (o == notStored) {
          continue;
        }
        const int f = first[b];
        const int c0 = upper ? std::max(f, r) : f;
        for (int col = c0; col < f + nc; ++col) {
          row[o + (col - c0)] += ke(i, b * nc + (col - f));
        }
      }
    }
  }
}

void StiffnessMatrix::add(int i, int j, double v) {
  accumulate(i, j, v);
  flushPending();
}

void StiffnessMatrix::accumulate(int i, int j, double v) {
  if (storage() == linalg::Storage::Upper && j < i) {
    return;
  }
  const std::int64_t k = cells_.pattern().find(i, j);
  if (k >= 0) {
    cells_.values()[static_cast<std::size_t>(k)] += v;
    return;
  }
  if (extra_.pattern().nonZeros() > 0) {
    const std::int64_t e = extra_.pattern().find(i, j);
    if (e >= 0) {
      extra_.values()[static_cast<std::size_t>(e)] += v;
      return;
    }
  }
  pending_.emplace_back(i, j, v);
}

void StiffnessMatrix::add(const std::vector<Eigen::Triplet<double>>& entries) {
  for (const auto& t : entries) {
    accumulate(static_cast<int>(t.row()), static_cast<int>(t.col()), t.value());
  }
  flushPending();
}

void StiffnessMatrix::add(const StiffnessMatrix& other) {
  const bool mirror = other.storage() == linalg::Storage::Upper;
  for (int i = 0; i < other.size(); ++i) {
    other.forEachInRow(i, [&](int j, double v) {
      accumulate(i, j, v);
      if (mirror && j != i) {
        accumulate(j, i, v);
      }
    });
  }
  flushPending();
}

void StiffnessMatrix::flushPending() {
  if (pending_.empty()) {
    return;
  }
  // Union of the extra pattern and the new pairs; the values of both summed.
  std::vector<std::pair<std::pair<int, int>, double>> all;
  const linalg::SparsePattern& e = extra_.pattern();
  all.reserve(static_cast<std::size_t>(e.nonZeros()) + pending_.size());
  for (int i = 0; i < e.size; ++i) {
    for (auto k = e.rowStart[static_cast<std::size_t>(i)]; k < e.rowStart[static_cast<std::size_t>(i) + 1];
         ++k) {
      all.push_back(
          {{i, e.columns[static_cast<std::size_t>(k)]}, extra_.values()[static_cast<std::size_t>(k)]});
    }
  }
  for (const auto& t : pending_) {
    all.push_back({{static_cast<int>(t.row()), static_cast<int>(t.col())}, t.value()});
  }
  pending_.clear();
  std::stable_sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::pair<int, int>> keys;
  std::vector<double> values;
  for (const auto& [key, v] : all) {
    if (!keys.empty() && keys.back() == key) {
      values.back() += v;
    } else {
      keys.push_back(key);
      values.push_back(v);
    }
  }
  extra_ = linalg::SparseMatrix(patternOf(size(), storage(), keys));
  extra_.values() = std::move(values);
  patternId_ = newPatternId();
}

double StiffnessMatrix::diagonal(int i) const {
  return cells_.values()[static_cast<std::size_t>(diagonal_[static_cast<std::size_t>(i)])];
}

Eigen::SparseMatrix<double> StiffnessMatrix::toEigen() const {
  std::vector<Eigen::Triplet<double>> t;
  const bool upper = storage() == linalg::Storage::Upper;
  for (int i = 0; i < size(); ++i) {
    forEachInRow(i, [&](int j, double v) {
      t.emplace_back(i, j, v);
      if (upper && j != i) {
        t.emplace_back(j, i, v);
      }
    });
  }
  Eigen::SparseMatrix<double> k(size(), size());
  k.setFromTriplets(t.begin(), t.end());
  return k;
}

std::size_t StiffnessMatrix::memoryBytes() const {
  auto bytesOf = [](const linalg::SparseMatrix& m) {
    return m.pattern().columns.capacity() * sizeof(int) +
           m.pattern().rowStart.capacity() * sizeof(std::int64_t) + m.values().capacity() * sizeof(double);
  };
  return bytesOf(cells_) + bytesOf(extra_) + diagonal_.capacity() * sizeof(std::int64_t) +
         cellStart_.capacity() * sizeof(std::int64_t) + cellFirstDof_.capacity() * sizeof(int) +
         offsetStart_.capacity() * sizeof(std::int64_t) + offsets_.capacity() * sizeof(std::uint16_t);
}

} // namespace stella
