#pragma once
// The 1-based coordinates (IRN, JCN) of a sparse pattern in MUMPS's centralised assembled format,
// shared by the double (DMUMPS) and single-precision (SMUMPS, GCPC LDLT_SP) backends.

#include "solver/linalg/SparseMatrix.hpp"

#include <cstddef>
#include <vector>

namespace stella::linalg {

template <typename Int>
void mumpsCoordinates(const SparsePattern& p, std::vector<Int>& irn, std::vector<Int>& jcn) {
  irn.resize(static_cast<std::size_t>(p.nonZeros()));
  jcn.resize(irn.size());
  for (int i = 0; i < p.size; ++i) {
    for (auto k = p.rowStart[static_cast<std::size_t>(i)]; k < p.rowStart[static_cast<std::size_t>(i) + 1];
         ++k) {
      irn[static_cast<std::size_t>(k)] = static_cast<Int>(i + 1);
      jcn[static_cast<std::size_t>(k)] = static_cast<Int>(p.columns[static_cast<std::size_t>(k)] + 1);
    }
  }
}

} // namespace stella::linalg
