// Point sets of the continuous contact integration schemes (see the header). Gauss-Legendre points
// are computed (Newton on the Legendre polynomial), Newton-Cotes weights solved from the moments
// of the lattice, the triangle's Gauss rules are the symmetric ones of degree 1 to 6.

#include "solver/contact/ContinuousIntegrationRule.hpp"

#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace stella::contact {

namespace {

enum class Shape { Segment, Triangle, Quadrangle };

Shape shapeOf(CellType type) {
  switch (type) {
  case CellType::SEG2:
  case CellType::SEG3:
    return Shape::Segment;
  case CellType::TRIA3:
  case CellType::TRIA6:
    return Shape::Triangle;
  case CellType::QUAD4:
  case CellType::QUAD8:
  case CellType::QUAD9:
    return Shape::Quadrangle;
  default:
    throw std::invalid_argument("contactIntegrationRule: no contact integration on a " +
                                std::string(name(type)) + " slave cell");
  }
}

// One-dimensional rule on [-1, 1].
struct Line {
  std::vector<double> x;
  std::vector<double> w;
  int degree = 0;
};

Line gaussLegendre(int n) {
  Line l;
  l.degree = 2 * n - 1;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0;
      double p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0); // P_n'(x) from P_n = p1, P_(n-1) = p0
      const double dx = p1 / derivative;
      x -= dx;
      if (std::fabs(dx) < 1e-16) {
        break;
      }
    }
    l.x.push_back(x);
    l.w.push_back(2.0 / ((1.0 - x * x) * derivative * derivative));
  }
  return l;
}

Line trapezoid() {
  return {{-1.0, 1.0}, {1.0, 1.0}, 1};
}

// Composite Simpson on 2m intervals of [-1, 1].
Line compositeSimpson(int m) {
  Line l;
  l.degree = 3;
  const double h = 1.0 / m;
  for (int i = 0; i <= 2 * m; ++i) {
    l.x.push_back(-1.0 + i * h);
    const double factor = (i == 0 || i == 2 * m) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    l.w.push_back(factor * h / 3.0);
  }
  return l;
}

// Closed Newton-Cotes with p + 1 equally spaced points: the weights integrating 1, x, ..., x^p.
Line newtonCotes(int p) {
  Line l;
  l.degree = p % 2 == 0 ? p + 1 : p;
  Eigen::MatrixXd v(p + 1, p + 1);
  Eigen::VectorXd moments(p + 1);
  for (int i = 0; i <= p; ++i) {
    l.x.push_back(-1.0 + 2.0 * i / p);
  }
  for (int k = 0; k <= p; ++k) {
    moments(k) = k % 2 == 0 ? 2.0 / (k + 1) : 0.0;
    for (int i = 0; i <= p; ++i) {
      v(k, i) = std::pow(l.x[static_cast<std::size_t>(i)], k);
    }
  }
  const Eigen::VectorXd w = v.fullPivLu().solve(moments);
  l.w.assign(w.data(), w.data() + w.size());
  return l;
}

ContactIntegrationRule fromLine(const Line& l) {
  ContactIntegrationRule r;
  r.degree = l.degree;
  for (std::size_t i = 0; i < l.x.size(); ++i) {
    r.points.emplace_back(l.x[i], 0.0, 0.0);
    r.weights.push_back(l.w[i]);
  }
  return r;
}

ContactIntegrationRule tensor(const Line& l) {
  ContactIntegrationRule r;
  r.degree = l.degree;
  for (std::size_t j = 0; j < l.x.size(); ++j) {
    for (std::size_t i = 0; i < l.x.size(); ++i) {
      r.points.emplace_back(l.x[i], l.x[j], 0.0);
      r.weights.push_back(l.w[i] * l.w[j]);
    }
  }
  return r;
}

// Symmetric orbits of the triangle (0,0)-(1,0)-(0,1), in barycentric terms.
void centroid(ContactIntegrationRule& r, double w) {
  r.points.emplace_back(1.0 / 3.0, 1.0 / 3.0, 0.0);
  r.weights.push_back(w);
}
void orbit3(ContactIntegrationRule& r, double a, double w) {
  for (const auto& [x, y] : {std::pair{a, a}, std::pair{1.0 - 2.0 * a, a}, std::pair{a, 1.0 - 2.0 * a}}) {
    r.points.emplace_back(x, y, 0.0);
    r.weights.push_back(w);
  }
}
void orbit6(ContactIntegrationRule& r, double a, double b, double w) {
  const double c = 1.0 - a - b;
  for (const auto& [x, y] : {std::pair{a, b}, std::pair{b, a}, std::pair{c, a}, std::pair{c, b},
                             std::pair{a, c}, std::pair{b, c}}) {
    r.points.emplace_back(x, y, 0.0);
    r.weights.push_back(w);
  }
}

// The symmetric Gauss rules of the triangle exact for degree n (weights summing to 1/2).
ContactIntegrationRule triangleGauss(int n) {
  ContactIntegrationRule r;
  r.degree = n;
  switch (n) {
  case 1:
    centroid(r, 0.5);
    break;
  case 2:
    orbit3(r, 1.0 / 6.0, 1.0 / 6.0);
    break;
  case 3:
    centroid(r, -27.0 / 96.0);
    orbit3(r, 0.2, 25.0 / 96.0);
    break;
  case 4:
    orbit3(r, 0.44594849091596488632, 0.22338158967801146570 / 2.0);
    orbit3(r, 0.09157621350977074346, 0.10995174365532186764 / 2.0);
    break;
  case 5: {
    const double s = std::sqrt(15.0);
    centroid(r, 9.0 / 80.0);
    orbit3(r, (6.0 + s) / 21.0, (155.0 + s) / 2400.0);
    orbit3(r, (6.0 - s) / 21.0, (155.0 - s) / 2400.0);
    break;
  }
  case 6:
    orbit3(r, 0.063089014491502228340, 0.050844906370206816921 / 2.0);
    orbit3(r, 0.249286745170910421292, 0.116786275726379366025 / 2.0);
    orbit6(r, 0.310352451033784405417, 0.053145049844816947353, 0.082851075618373575194 / 2.0);
    break;
  default:
    throw std::invalid_argument("contactIntegrationRule: GAUSS ORDRE_INT " + std::to_string(n) +
                                " not in 1..6");
  }
  return r;
}

// The m^2 sub-triangles of step 1/m, each integrated with its vertices (1/15 of its area) and
// edge midpoints (4/15): weights accumulated on the lattice of step 1/(2m).
ContactIntegrationRule triangleSimpson(int m) {
  ContactIntegrationRule r;
  r.degree = 1;
  const int h = 2 * m;
  std::vector<std::vector<double>> weight(static_cast<std::size_t>(h + 1), std::vector<double>(h + 1, 0.0));
  const double area = 0.5 / (m * m);
  const auto add = [&](std::array<std::array<int, 2>, 3> v) {
    for (int k = 0; k < 3; ++k) {
      const auto& p = v[static_cast<std::size_t>(k)];
      const auto& q = v[static_cast<std::size_t>((k + 1) % 3)];
      weight[static_cast<std::size_t>(p[0])][static_cast<std::size_t>(p[1])] += area / 15.0;
      weight[static_cast<std::size_t>((p[0] + q[0]) / 2)][static_cast<std::size_t>((p[1] + q[1]) / 2)] +=
          4.0 * area / 15.0;
    }
  };
  for (int i = 0; i < m; ++i) {
    for (int j = 0; i + j < m; ++j) {
      add({{{2 * i, 2 * j}, {2 * i + 2, 2 * j}, {2 * i, 2 * j + 2}}});
      if (i + j + 1 < m) {
        add({{{2 * i + 2, 2 * j}, {2 * i + 2, 2 * j + 2}, {2 * i, 2 * j + 2}}});
      }
    }
  }
  for (int j = 0; j <= h; ++j) {
    for (int i = 0; i + j <= h; ++i) {
      r.points.emplace_back(static_cast<double>(i) / h, static_cast<double>(j) / h, 0.0);
      r.weights.push_back(weight[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
    }
  }
  return r;
}

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

// The interpolatory rule on the triangle's lattice of step 1/p: exact for every monomial of
// degree <= p (the lattice is unisolvent for them).
ContactIntegrationRule triangleNewtonCotes(int p) {
  ContactIntegrationRule r;
  r.degree = p;
  for (int j = 0; j <= p; ++j) {
    for (int i = 0; i + j <= p; ++i) {
      r.points.emplace_back(static_cast<double>(i) / p, static_cast<double>(j) / p, 0.0);
    }
  }
  const auto n = static_cast<Eigen::Index>(r.points.size());
  Eigen::MatrixXd v(n, n);
  Eigen::VectorXd moments(n);
  Eigen::Index row = 0;
  for (int d = 0; d <= p; ++d) {
    for (int a = 0; a <= d; ++a) {
      const int b = d - a;
      moments(row) = factorial(a) * factorial(b) / factorial(a + b + 2);
      for (Eigen::Index i = 0; i < n; ++i) {
        const auto& x = r.points[static_cast<std::size_t>(i)];
        v(row, i) = std::pow(x[0], a) * std::pow(x[1], b);
      }
      ++row;
    }
  }
  const Eigen::VectorXd w = v.fullPivLu().solve(moments);
  r.weights.assign(w.data(), w.data() + w.size());
  return r;
}

void checkOrder(ContactIntegration scheme, int order, int low, int high) {
  if (order < low || order > high) {
    throw std::invalid_argument(std::string("contactIntegrationRule: ") + integrationName(scheme) +
                                " ORDRE_INT " + std::to_string(order) + " not in " + std::to_string(low) +
                                ".." + std::to_string(high));
  }
}

ContactIntegrationRule schemeRule(Shape shape, ContactIntegration scheme, int order) {
  switch (scheme) {
  case ContactIntegration::Gauss:
    checkOrder(scheme, order, 1, 6);
    return shape == Shape::Segment    ? fromLine(gaussLegendre(order))
           : shape == Shape::Triangle ? triangleGauss(order)
                                      : tensor(gaussLegendre(order));
  case ContactIntegration::Simpson:
    checkOrder(scheme, order, 1, 4);
    return shape == Shape::Segment    ? fromLine(compositeSimpson(order))
           : shape == Shape::Triangle ? triangleSimpson(order)
                                      : tensor(compositeSimpson(order));
  case ContactIntegration::NewtonCotes:
    checkOrder(scheme, order, 3, 8);
    return shape == Shape::Segment    ? fromLine(newtonCotes(order))
           : shape == Shape::Triangle ? triangleNewtonCotes(order)
                                      : tensor(newtonCotes(order));
  case ContactIntegration::Auto:
    break;
  }
  throw std::invalid_argument("contactIntegrationRule: AUTO has no order");
}

// code_aster's AUTO: the nodes with trapezoid weights on the linear cells, Simpson's 3 (3 x 3)
// points on SEG3, QUAD8 and QUAD9, the degree-4 Gauss rule on TRIA6.
ContactIntegrationRule autoRule(CellType type) {
  switch (type) {
  case CellType::TRIA3: {
    ContactIntegrationRule r;
    r.degree = 1;
    r.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    r.weights = {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
    return r;
  }
  case CellType::QUAD4:
    return tensor(trapezoid());
  case CellType::SEG3:
    return fromLine(compositeSimpson(1));
  case CellType::SEG2:
    return fromLine(trapezoid());
  case CellType::QUAD8:
  case CellType::QUAD9:
    return tensor(compositeSimpson(1));
  case CellType::TRIA6:
    return triangleGauss(4);
  default:
    break;
  }
  return {};
}

} // namespace

bool ContactIntegrationRule::atNodes() const {
  std::vector<char> seen(static_cast<std::size_t>(cellNodes), 0);
  for (int n : node) {
    if (n < 0 || seen[static_cast<std::size_t>(n)] != 0) {
      return false;
    }
    seen[static_cast<std::size_t>(n)] = 1;
  }
  return static_cast<int>(node.size()) == cellNodes;
}

bool contactIntegrationDefined(CellType type) {
  return type == CellType::SEG2 || type == CellType::SEG3 || type == CellType::TRIA3 ||
         type == CellType::TRIA6 || type == CellType::QUAD4 || type == CellType::QUAD8 ||
         type == CellType::QUAD9;
}

const char* integrationName(ContactIntegration scheme) {
  switch (scheme) {
  case ContactIntegration::Auto:
    return "AUTO";
  case ContactIntegration::Gauss:
    return "GAUSS";
  case ContactIntegration::Simpson:
    return "SIMPSON";
  case ContactIntegration::NewtonCotes:
    return "NCOTES";
  }
  return "?";
}

ContactIntegrationRule contactIntegrationRule(CellType type, ContactIntegration scheme, int order) {
  const Shape shape = shapeOf(type);
  ContactIntegrationRule r =
      scheme == ContactIntegration::Auto ? autoRule(type) : schemeRule(shape, scheme, order);
  const fem::ReferenceElement& ref = fem::referenceElement(type);
  r.cellNodes = ref.nodeCount();
  r.node.assign(r.points.size(), -1);
  for (std::size_t p = 0; p < r.points.size(); ++p) {
    for (int i = 0; i < ref.nodeCount(); ++i) {
      if ((ref.node(i) - r.points[p]).norm() < 1e-12) {
        r.node[p] = i;
      }
    }
  }
  return r;
}

double skinCellJacobian(const fem::ReferenceElement& ref, const std::vector<Point3>& x,
                        const Eigen::Vector3d& xi) {
  const Eigen::MatrixXd d = ref.gradients(xi);
  Point3 t1{0, 0, 0};
  Point3 t2{0, 0, 0};
  for (int k = 0; k < ref.nodeCount(); ++k) {
    const auto& p = x[static_cast<std::size_t>(k)];
    t1 = t1 + d(k, 0) * p;
    if (ref.dimension() == 2) {
      t2 = t2 + d(k, 1) * p;
    }
  }
  return ref.dimension() == 2 ? norm(cross(t1, t2)) : norm(t1);
}

} // namespace stella::contact
