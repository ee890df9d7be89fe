// SymmetricTangent: (K + K^T) / 2 of a fully stored tangent, in upper storage.

#include "solver/nonlinear/SymmetricTangent.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>

namespace stella {

StiffnessMatrix& symmetricPart(const StiffnessMatrix& full, StiffnessMatrix& upper) {
  STELLA_ASSERT(full.storage() == linalg::Storage::Full && upper.storage() == linalg::Storage::Upper &&
                    full.size() == upper.size(),
                "symmetricPart: a full matrix into an upper one of the same size");
  for (int i = 0; i < full.size(); ++i) {
    full.forEachInRow(i, [&](int j, double v) {
      // K(i, j) and K(j, i) both land on the upper entry (min, max), half each.
      upper.add(std::min(i, j), std::max(i, j), i == j ? v : 0.5 * v);
    });
  }
  return upper;
}

} // namespace stella
