// Reference elements: node tables (code_aster R3.01.01 coordinates and orderings) and the
// function spaces their shape functions span.

#include "solver/fem/ReferenceElement.hpp"

#include "solver/fem/Dual.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

namespace stella::fem {
namespace {

using Basis = std::vector<Dual3>;
using Coords = std::array<Dual3, 3>;

// Products of the given factors with every entry of `terms`.
void appendProducts(Basis& out, const Basis& a, const Basis& b) {
  for (const auto& x : a) {
    for (const auto& y : b) {
      out.push_back(x * y);
    }
  }
}

Basis line(const Dual3& t, int degree) {
  Basis b{Dual3::constant(1.0)};
  for (int k = 1; k <= degree; ++k) {
    b.push_back(b.back() * t);
  }
  return b;
}

// Complete polynomials of degree <= p in two variables.
Basis triangle(const Dual3& s, const Dual3& t, int degree) {
  Basis b{Dual3::constant(1.0), s, t};
  if (degree >= 2) {
    b.push_back(s * s);
    b.push_back(s * t);
    b.push_back(t * t);
  }
  return b;
}

// The function space of each cell type, evaluated at x.
Basis basisFunctions(CellType type, const Coords& c) {
  const Dual3 &x = c[0], &y = c[1], &z = c[2];
  const Dual3 one = Dual3::constant(1.0);
  Basis b;
  switch (type) {
  case CellType::SEG2:
    return line(x, 1);
  case CellType::SEG3:
    return line(x, 2);
  case CellType::TRIA3:
    return triangle(x, y, 1);
  case CellType::TRIA6:
    return triangle(x, y, 2);
  case CellType::QUAD4:
    appendProducts(b, line(x, 1), line(y, 1));
    return b;
  case CellType::QUAD9:
    appendProducts(b, line(x, 2), line(y, 2));
    return b;
  case CellType::QUAD8: // serendipity
    return {one, x, y, x * y, x * x, y * y, x * x * y, x * y * y};
  case CellType::TETRA4:
    return {one, x, y, z};
  case CellType::TETRA10:
    return {one, x, y, z, x * x, y * y, z * z, x * y, x * z, y * z};
  case CellType::PENTA6: // x is the prism axis, (y, z) the triangle
    appendProducts(b, line(x, 1), triangle(y, z, 1));
    return b;
  case CellType::PENTA18:
    appendProducts(b, line(x, 2), triangle(y, z, 2));
    return b;
  case CellType::PENTA15:
    appendProducts(b, line(x, 1), triangle(y, z, 2));
    b.push_back(x * x);
    b.push_back(x * x * y);
    b.push_back(x * x * z);
    return b;
  case CellType::HEXA8:
    appendProducts(b, line(x, 1), line(y, 1));
    {
      Basis r;
      appendProducts(r, b, line(z, 1));
      return r;
    }
  case CellType::HEXA27:
    appendProducts(b, line(x, 2), line(y, 2));
    {
      Basis r;
      appendProducts(r, b, line(z, 2));
      return r;
    }
  case CellType::HEXA20: // serendipity
    return {one,
            x,
            y,
            z,
            x * y,
            y * z,
            x * z,
            x * x,
            y * y,
            z * z,
            x * y * z,
            x * x * y,
            x * x * z,
            y * y * x,
            y * y * z,
            z * z * x,
            z * z * y,
            x * x * y * z,
            y * y * x * z,
            z * z * x * y};
  case CellType::PYRAM5:
  case CellType::PYRAM13: {
    // code_aster's base vertices are (+-1, 0, 0), (0, +-1, 0): in a = x + y, b = y - x the base
    // is the square |a|, |b| <= 1 - z. Rational terms carry 1/(1 - z) and vanish at the apex.
    const Dual3 a = x + y;
    const Dual3 bb = y - x;
    const Dual3 w = one - z;
    const bool apex = std::abs(w.v) < 1e-14;
    auto overW = [&](const Dual3& num) { return apex ? Dual3::constant(0.0) : num / w; };
    if (type == CellType::PYRAM5) {
      return {one, a, bb, z, overW(a * bb)};
    }
    return {one,
            a,
            bb,
            z,
            a * a,
            bb * bb,
            z * z,
            a * z,
            bb * z,
            overW(a * bb),
            overW(a * a * bb),
            overW(a * bb * bb),
            overW(a * bb * z)};
  }
  default:
    throw std::invalid_argument("no reference element for cell type " + std::string(name(type)));
  }
}

Coords dualAt(const Eigen::Vector3d& xi) {
  return {Dual3::variable(xi[0], 0), Dual3::variable(xi[1], 1), Dual3::variable(xi[2], 2)};
}

struct NodeTable {
  int dimension;
  double measure;
  std::vector<std::array<double, 3>> nodes;
};

// Node coordinates from code_aster's reference documentation R3.01.01.
NodeTable nodeTable(CellType type) {
  const std::vector<std::array<double, 3>> hexVertices{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                                       {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const std::vector<std::array<double, 3>> hexEdges{{0, -1, -1}, {1, 0, -1}, {0, 1, -1}, {-1, 0, -1},
                                                    {-1, -1, 0}, {1, -1, 0}, {1, 1, 0},  {-1, 1, 0},
                                                    {0, -1, 1},  {1, 0, 1},  {0, 1, 1},  {-1, 0, 1}};
  const std::vector<std::array<double, 3>> hexFaces{{0, 0, -1}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0},
                                                    {-1, 0, 0}, {0, 0, 1},  {0, 0, 0}};
  const std::vector<std::array<double, 3>> tetVertices{{0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {1, 0, 0}};
  const std::vector<std::array<double, 3>> tetEdges{{0, 0.5, 0.5}, {0, 0, 0.5},   {0, 0.5, 0},
                                                    {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0.5, 0, 0}};
  const std::vector<std::array<double, 3>> prismVertices{{-1, 1, 0}, {-1, 0, 1}, {-1, 0, 0},
                                                         {1, 1, 0},  {1, 0, 1},  {1, 0, 0}};
  const std::vector<std::array<double, 3>> prismEdges{{-1, 0.5, 0.5}, {-1, 0, 0.5}, {-1, 0.5, 0},
                                                      {0, 1, 0},      {0, 0, 1},    {0, 0, 0},
                                                      {1, 0.5, 0.5},  {1, 0, 0.5},  {1, 0.5, 0}};
  const std::vector<std::array<double, 3>> prismFaces{{0, 0.5, 0.5}, {0, 0, 0.5}, {0, 0.5, 0}};
  const std::vector<std::array<double, 3>> pyramidVertices{
      {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}};
  const std::vector<std::array<double, 3>> pyramidEdges{{0.5, 0.5, 0},  {-0.5, 0.5, 0}, {-0.5, -0.5, 0},
                                                        {0.5, -0.5, 0}, {0.5, 0, 0.5},  {0, 0.5, 0.5},
                                                        {-0.5, 0, 0.5}, {0, -0.5, 0.5}};
  auto join = [](std::vector<std::array<double, 3>> a, const std::vector<std::array<double, 3>>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<std::array<double, 3>> quadVertices{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const std::vector<std::array<double, 3>> quadEdges{{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  const std::vector<std::array<double, 3>> triVertices{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::array<double, 3>> triEdges{{0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}};
  switch (type) {
  case CellType::SEG2:
    return {1, 2.0, {{-1, 0, 0}, {1, 0, 0}}};
  case CellType::SEG3:
    return {1, 2.0, {{-1, 0, 0}, {1, 0, 0}, {0, 0, 0}}};
  case CellType::TRIA3:
    return {2, 0.5, triVertices};
  case CellType::TRIA6:
    return {2, 0.5, join(triVertices, triEdges)};
  case CellType::QUAD4:
    return {2, 4.0, quadVertices};
  case CellType::QUAD8:
    return {2, 4.0, join(quadVertices, quadEdges)};
  case CellType::QUAD9:
    return {2, 4.0, join(join(quadVertices, quadEdges), {{0, 0, 0}})};
  case CellType::TETRA4:
    return {3, 1.0 / 6.0, tetVertices};
  case CellType::TETRA10:
    return {3, 1.0 / 6.0, join(tetVertices, tetEdges)};
  case CellType::PENTA6:
    return {3, 1.0, prismVertices};
  case CellType::PENTA15:
    return {3, 1.0, join(prismVertices, prismEdges)};
  case CellType::PENTA18:
    return {3, 1.0, join(join(prismVertices, prismEdges), prismFaces)};
  case CellType::PYRAM5:
    return {3, 2.0 / 3.0, pyramidVertices};
  case CellType::PYRAM13:
    return {3, 2.0 / 3.0, join(pyramidVertices, pyramidEdges)};
  case CellType::HEXA8:
    return {3, 8.0, hexVertices};
  case CellType::HEXA20:
    return {3, 8.0, join(hexVertices, hexEdges)};
  case CellType::HEXA27:
    return {3, 8.0, join(join(hexVertices, hexEdges), hexFaces)};
  default:
    throw std::invalid_argument("no reference element for cell type " + std::string(name(type)));
  }
}

std::unique_ptr<ReferenceElement> build(CellType type) {
  NodeTable t = nodeTable(type);
  std::vector<Eigen::Vector3d> nodes;
  nodes.reserve(t.nodes.size());
  for (const auto& n : t.nodes) {
    nodes.emplace_back(n[0], n[1], n[2]);
  }
  return std::make_unique<ReferenceElement>(type, t.dimension, std::move(nodes), t.measure);
}

} // namespace

ReferenceElement::ReferenceElement(CellType type, int dimension, std::vector<Eigen::Vector3d> nodes,
                                   double measure)
    : type_(type), dimension_(dimension), nodes_(std::move(nodes)), measure_(measure) {
  const auto n = static_cast<Eigen::Index>(nodes_.size());
  Eigen::MatrixXd vandermonde(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Basis b = basisFunctions(type_, dualAt(nodes_[static_cast<std::size_t>(i)]));
    if (static_cast<Eigen::Index>(b.size()) != n) {
      throw std::logic_error("reference element " + std::string(name(type_)) +
                             ": basis size differs from node count");
    }
    for (Eigen::Index j = 0; j < n; ++j) {
      vandermonde(i, j) = b[static_cast<std::size_t>(j)].v;
    }
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(vandermonde);
  if (!lu.isInvertible()) {
    throw std::logic_error("reference element " + std::string(name(type_)) +
                           ": nodes not unisolvent for the basis");
  }
  coefficients_ = lu.inverse();
}

void ReferenceElement::evaluate(const Eigen::Vector3d& xi, Eigen::VectorXd* values,
                                Eigen::MatrixXd* gradients) const {
  const Basis b = basisFunctions(type_, dualAt(xi));
  const auto n = static_cast<Eigen::Index>(b.size());
  Eigen::VectorXd v(n);
  Eigen::MatrixXd d(n, dimension_);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& bj = b[static_cast<std::size_t>(j)];
    v[j] = bj.v;
    for (int k = 0; k < dimension_; ++k) {
      d(j, k) = bj.d[static_cast<std::size_t>(k)];
    }
  }
  if (values != nullptr) {
    *values = coefficients_.transpose() * v;
  }
  if (gradients != nullptr) {
    *gradients = coefficients_.transpose() * d;
  }
}

Eigen::VectorXd ReferenceElement::values(const Eigen::Vector3d& xi) const {
  Eigen::VectorXd v;
  evaluate(xi, &v, nullptr);
  return v;
}

Eigen::MatrixXd ReferenceElement::gradients(const Eigen::Vector3d& xi) const {
  Eigen::MatrixXd g;
  evaluate(xi, nullptr, &g);
  return g;
}

CellType ReferenceElement::linearType() const {
  switch (type_) {
  case CellType::SEG3:
    return CellType::SEG2;
  case CellType::TRIA6:
    return CellType::TRIA3;
  case CellType::QUAD8:
  case CellType::QUAD9:
    return CellType::QUAD4;
  case CellType::TETRA10:
    return CellType::TETRA4;
  case CellType::PENTA15:
  case CellType::PENTA18:
    return CellType::PENTA6;
  case CellType::PYRAM13:
    return CellType::PYRAM5;
  case CellType::HEXA20:
  case CellType::HEXA27:
    return CellType::HEXA8;
  default:
    return type_;
  }
}

const ReferenceElement& referenceElement(CellType type) {
  static std::array<std::unique_ptr<ReferenceElement>, cellTypeCount> cache;
  static std::array<std::once_flag, cellTypeCount> once;
  const auto i = static_cast<std::size_t>(type);
  std::call_once(once[i], [&] { cache[i] = build(type); });
  return *cache[i];
}

} // namespace stella::fem
