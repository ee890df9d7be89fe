// GaussExtrapolation: least-squares Gauss -> vertex fit of the linear cell, then linear
// interpolation of the vertex values to the other nodes (see the header).

#include "solver/fem/GaussExtrapolation.hpp"

#include "solver/fem/ReferenceElement.hpp"

#include <array>
#include <memory>
#include <mutex>

namespace stella::fem {

Eigen::MatrixXd buildGaussToNodeMatrix(CellType type, const QuadratureRule& rule) {
  const ReferenceElement& element = referenceElement(type);
  const int nodes = element.nodeCount();
  const int points = rule.size();
  if (points == 1) {
    return Eigen::MatrixXd::Ones(nodes, 1);
  }
  const ReferenceElement& linear = referenceElement(element.linearType());
  const int vertices = linear.nodeCount();
  Eigen::MatrixXd a(points, vertices);
  for (int g = 0; g < points; ++g) {
    a.row(g) = linear.values(rule.points[static_cast<std::size_t>(g)]).transpose();
  }
  // vertices x points: the least-squares fit (the exact inverse when square).
  const Eigen::MatrixXd fit = (a.transpose() * a).ldlt().solve(a.transpose());
  Eigen::MatrixXd out(nodes, points);
  for (int k = 0; k < nodes; ++k) {
    const Eigen::VectorXd w = linear.values(element.node(k));
    out.row(k) = w.transpose() * fit;
  }
  return out;
}

const Eigen::MatrixXd& gaussToNodeMatrix(CellType type, IntegrationRole role) {
  static std::array<std::array<std::unique_ptr<Eigen::MatrixXd>, integrationRoleCount>, cellTypeCount> cache;
  static std::array<std::array<std::once_flag, integrationRoleCount>, cellTypeCount> once;
  const auto i = static_cast<std::size_t>(type);
  const auto j = static_cast<std::size_t>(role);
  std::call_once(once[i][j], [&] {
    cache[i][j] = std::make_unique<Eigen::MatrixXd>(buildGaussToNodeMatrix(type, rigiRule(type, role)));
  });
  return *cache[i][j];
}

} // namespace stella::fem
