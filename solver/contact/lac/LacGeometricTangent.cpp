// The consistent geometric tangent of LAC contact with ALGO_RESO_GEOM='NEWTON' in 2D (see
// LacContactConstraint.hpp). The pairing is redone at every Newton iterate, so the residual's
// contact force of a patch in contact is f_P(u) = -(lambda_P + rho g_P(u)) c_P(u), with
// g_P = G_P / L_P and c_P the gap's gradient with the geometry held (LacPatchRow::gradient), and
// its mean-gap equation g_P(u) = 0. Their exact derivatives (LacPairing's gapDerivative,
// lengthDerivative, gradientDerivative: forward-mode duals through the overlap ends, Gauss points,
// normals, master points and Jacobians, LacOverlapTerms.hpp) make Newton converge quadratically
// when the geometry changes; the tangent is not symmetric (c_P differs from dG_P/du).

#include "solver/contact/lac/LacContactConstraint.hpp"

#include <map>

namespace stella::contact::lac {

std::vector<std::pair<int, double>> LacContactConstraint::exactGapRow(std::size_t p) const {
  const LacPatchRow& r = rows_[p];
  const double g = r.integratedGap / r.pairedLength;
  std::map<int, double> row;
  for (const auto& [e, v] : r.gapDerivative) {
    row[e] += v / r.pairedLength;
  }
  for (const auto& [e, v] : r.lengthDerivative) {
    row[e] -= g * v / r.pairedLength;
  }
  return {row.begin(), row.end()};
}

std::vector<std::pair<int, double>> LacContactConstraint::gapRow(std::size_t p) const {
  if (consistent_) {
    return gapRows_[p];
  }
  std::vector<std::pair<int, double>> row;
  row.reserve(rows_[p].gradient.size());
  for (const auto& [e, v] : rows_[p].gradient) {
    row.emplace_back(e, v / rows_[p].pairedLength);
  }
  return row;
}

void LacContactConstraint::addGeometricTangent(std::size_t p, bool on, double pressure,
                                               std::vector<Eigen::Triplet<double>>& tangent) const {
  const LacPatchRow& r = rows_[p];
  const double augmented = on ? rho_ : 0.0;
  for (const auto& [i, ci] : r.gradient) {
    for (const auto& [j, gj] : gapRows_[p]) {
      tangent.emplace_back(i, j, augmented * ci * gj);
    }
  }
  for (const auto& d : r.gradientDerivative) {
    tangent.emplace_back(d.row, d.column, on ? pressure * d.value : 0.0);
  }
}

} // namespace stella::contact::lac
