#include "solver/post/SkinPressure.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/MeshGeometry.hpp"

namespace stella {

namespace {

// Unit normal of skin cell c at its local node i.
Point3 normalAtNode(const Mesh& mesh, const std::vector<Point3>& x, CellId c, int i) {
  const auto& ref = fem::referenceElement(mesh.cellType(c));
  const Eigen::MatrixXd g = ref.gradients(ref.node(i));
  const auto nodes = mesh.cellNodes(c);
  Point3 t[2] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  for (int d = 0; d < ref.dimension(); ++d) {
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      t[d] = t[d] + g(static_cast<Eigen::Index>(k), d) * x[static_cast<std::size_t>(nodes[k])];
    }
  }
  const Point3 n = ref.dimension() == 1 ? Point3{t[0][1], -t[0][0], 0.0} : cross(t[0], t[1]);
  const double length = norm(n);
  STELLA_ASSERT(length > 0.0, "degenerate skin cell");
  return (1.0 / length) * n;
}

// -n.sigma.n with the stress components of `sigma` at node `node`.
double normalPressure(const Field& sigma, const std::vector<std::size_t>& index, NodeId node,
                      const Point3& n) {
  const auto v = [&](std::size_t k) {
    return k < index.size() ? sigma.value(static_cast<std::size_t>(node), index[k]) : 0.0;
  };
  const double xx = v(0), yy = v(1), zz = v(2), xy = v(3), xz = v(4), yz = v(5);
  const double nn = xx * n[0] * n[0] + yy * n[1] * n[1] + zz * n[2] * n[2] + 2.0 * xy * n[0] * n[1] +
                    2.0 * xz * n[0] * n[2] + 2.0 * yz * n[1] * n[2];
  return -nn;
}

} // namespace

Field skinPressure(const Mesh& mesh, const std::vector<Point3>& x, const Field& nodalStress,
                   const std::vector<CellId>& skin) {
  std::vector<std::size_t> index;
  for (const char* name : {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"}) {
    if (const auto i = nodalStress.componentIndex(name)) {
      index.push_back(*i);
    } else {
      break;
    }
  }
  STELLA_ASSERT(index.size() >= 4, "the stress field has no SIXX, SIYY, SIZZ, SIXY");
  const auto nodeCount = static_cast<std::size_t>(mesh.nodeCount());
  std::vector<double> sum(nodeCount, 0.0);
  std::vector<int> count(nodeCount, 0);
  for (const CellId c : skin) {
    const auto nodes = mesh.cellNodes(c);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const NodeId n = nodes[i];
      if (!nodalStress.defined(static_cast<std::size_t>(n), index[0])) {
        continue; // no volume cell of the model holds the node
      }
      sum[static_cast<std::size_t>(n)] +=
          normalPressure(nodalStress, index, n, normalAtNode(mesh, x, c, static_cast<int>(i)));
      ++count[static_cast<std::size_t>(n)];
    }
  }
  Field out = Field::nodal("PRES_R", {"PRES"}, nodeCount);
  out.markPartial();
  for (std::size_t n = 0; n < nodeCount; ++n) {
    if (count[n] > 0) {
      out.value(n, 0) = sum[n] / count[n];
      out.setDefined(n, 0);
    }
  }
  return out;
}

} // namespace stella
