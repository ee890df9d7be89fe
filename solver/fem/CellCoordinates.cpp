// The coordinates of a cell's nodes (see the header).

#include "solver/fem/CellCoordinates.hpp"

namespace stella {

Eigen::MatrixXd cellCoordinates(const Mesh& mesh, CellId c, int dim) {
  const auto nodes = mesh.cellNodes(c);
  Eigen::MatrixXd x(static_cast<Eigen::Index>(nodes.size()), dim);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Point3 p = mesh.point(nodes[i]);
    for (int d = 0; d < dim; ++d) {
      x(static_cast<Eigen::Index>(i), d) = p[static_cast<std::size_t>(d)];
    }
  }
  return x;
}

} // namespace stella
