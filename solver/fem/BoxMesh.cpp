// Structured box meshes for every volume cell type.

#include "solver/fem/BoxMesh.hpp"

#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/Mesh.hpp"

#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace stella::fem {
namespace {

using Templates = std::vector<std::vector<int>>;

// Sub-cells of one hexahedron (vertices 0-7 in code_aster order, 8 = centre) or quadrangle.
Templates decomposition(CellType linear) {
  switch (linear) {
  case CellType::HEXA8:
    return {{0, 1, 2, 3, 4, 5, 6, 7}};
  case CellType::TETRA4:
    return {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  case CellType::PENTA6:
    return {{0, 1, 2, 4, 5, 6}, {0, 2, 3, 4, 6, 7}};
  case CellType::PYRAM5:
    return {{0, 1, 2, 3, 8}, {7, 6, 5, 4, 8}, {0, 4, 5, 1, 8},
            {1, 5, 6, 2, 8}, {2, 6, 7, 3, 8}, {3, 7, 4, 0, 8}};
  case CellType::QUAD4:
    return {{0, 1, 2, 3}};
  case CellType::TRIA3:
    return {{0, 1, 2}, {0, 2, 3}};
  default:
    throw std::invalid_argument("boxMesh: unsupported cell type");
  }
}

// Vertex permutation that reverses a cell's orientation.
void reverse(CellType linear, std::vector<Eigen::Vector3d>& v) {
  auto sw = [&](int a, int b) { std::swap(v[static_cast<std::size_t>(a)], v[static_cast<std::size_t>(b)]); };
  switch (linear) {
  case CellType::TRIA3:
  case CellType::TETRA4:
    sw(1, 2);
    break;
  case CellType::QUAD4:
  case CellType::PYRAM5:
    sw(1, 3);
    break;
  case CellType::PENTA6:
    sw(1, 2);
    sw(4, 5);
    break;
  case CellType::HEXA8:
    sw(1, 3);
    sw(5, 7);
    break;
  default:
    break;
  }
}

struct KeyHash {
  std::size_t operator()(const std::array<long long, 3>& k) const {
    return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
  }
};

} // namespace

PlainMesh boxMesh(CellType type, std::array<int, 3> divisions, std::array<double, 3> lengths) {
  const ReferenceElement& target = referenceElement(type);
  const CellType linear = target.linearType();
  const ReferenceElement& lin = referenceElement(linear);
  const int dim = target.dimension();
  // linear shape functions at the target's nodes: x_k = sum_v Nlin_v(xi_k) x_v
  std::vector<Eigen::VectorXd> map;
  for (int k = 0; k < target.nodeCount(); ++k) {
    map.push_back(lin.values(target.node(k)));
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int k = 0; k < lin.nodeCount(); ++k) {
    centroid += lin.node(k) / lin.nodeCount();
  }
  const Eigen::MatrixXd centroidGradients = lin.gradients(centroid);

  PlainMesh mesh;
  mesh.dimension = dim;
  mesh.cellType = type;
  std::vector<Eigen::Vector3d> nodes;
  std::unordered_map<std::array<long long, 3>, int, KeyHash> index;
  const double quantum = 1e-9 * std::max({lengths[0], lengths[1], dim == 3 ? lengths[2] : 0.0});
  auto nodeId = [&](const Eigen::Vector3d& p) {
    const std::array<long long, 3> key{std::llround(p[0] / quantum), std::llround(p[1] / quantum),
                                       std::llround(p[2] / quantum)};
    auto [it, inserted] = index.try_emplace(key, static_cast<int>(nodes.size()));
    if (inserted) {
      nodes.push_back(p);
    }
    return it->second;
  };
  const Templates parts = decomposition(linear);
  const int nz = dim == 3 ? divisions[2] : 1;
  const double hx = lengths[0] / divisions[0], hy = lengths[1] / divisions[1];
  const double hz = dim == 3 ? lengths[2] / divisions[2] : 0.0;
  std::vector<Eigen::Vector3d> corner(9);
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < divisions[1]; ++j) {
      for (int i = 0; i < divisions[0]; ++i) {
        const double x0 = i * hx, y0 = j * hy, z0 = k * hz;
        const double xs[] = {x0, x0 + hx, x0 + hx, x0};
        const double ys[] = {y0, y0, y0 + hy, y0 + hy};
        for (int c = 0; c < 4; ++c) {
          corner[static_cast<std::size_t>(c)] = Eigen::Vector3d(xs[c], ys[c], z0);
          corner[static_cast<std::size_t>(c + 4)] = Eigen::Vector3d(xs[c], ys[c], z0 + hz);
        }
        corner[8] = Eigen::Vector3d(x0 + 0.5 * hx, y0 + 0.5 * hy, z0 + 0.5 * hz);
        for (const auto& part : parts) {
          std::vector<Eigen::Vector3d> v;
          for (int c : part) {
            v.push_back(corner[static_cast<std::size_t>(c)]);
          }
          Eigen::MatrixXd xv(static_cast<Eigen::Index>(v.size()), dim);
          for (std::size_t a = 0; a < v.size(); ++a) {
            xv.row(static_cast<Eigen::Index>(a)) = v[a].head(dim).transpose();
          }
          if ((xv.transpose() * centroidGradients).determinant() < 0.0) {
            reverse(linear, v);
          }
          for (const auto& nk : map) {
            Eigen::Vector3d p = Eigen::Vector3d::Zero();
            for (std::size_t a = 0; a < v.size(); ++a) {
              p += nk[static_cast<Eigen::Index>(a)] * v[a];
            }
            mesh.connectivity.push_back(nodeId(p));
          }
        }
      }
    }
  }
  mesh.coordinates.resize(static_cast<Eigen::Index>(nodes.size()), dim);
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    mesh.coordinates.row(static_cast<Eigen::Index>(n)) = nodes[n].head(dim).transpose();
  }
  return mesh;
}

std::shared_ptr<Mesh> toMesh(const PlainMesh& p) {
  auto mesh = std::make_shared<Mesh>();
  mesh->setDimension(p.dimension);
  for (int n = 0; n < p.nodeCount(); ++n) {
    Point3 x{0, 0, 0};
    for (int d = 0; d < p.dimension; ++d) {
      x[static_cast<std::size_t>(d)] = p.coordinates(n, d);
    }
    mesh->addNode(x);
  }
  for (int c = 0; c < p.cellCount(); ++c) {
    mesh->addCell(p.cellType, std::span<const NodeId>(p.cell(c), static_cast<std::size_t>(p.nodesPerCell())));
  }
  return mesh;
}

} // namespace stella::fem
