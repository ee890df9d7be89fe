// Gauss rules on the reference shapes (segment [-1,1], triangle and tetrahedron unit simplices,
// quadrangle/hexahedron [-1,1]^d, prism = [-1,1] x triangle, pyramid |x|+|y| <= 1-z) and the
// rule code_aster's RIGI family uses for each cell type.

#include "solver/fem/Quadrature.hpp"

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace stella::fem {
namespace {

using Point = Eigen::Vector3d;

struct Rule1D {
  std::vector<double> x, w;
};

Rule1D gaussLegendre(int n) {
  switch (n) {
  case 1:
    return {{0.0}, {2.0}};
  case 2: {
    const double a = 1.0 / std::sqrt(3.0);
    return {{-a, a}, {1.0, 1.0}};
  }
  case 3: {
    const double a = std::sqrt(0.6);
    return {{-a, 0.0, a}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
  }
  case 4: {
    const double a = std::sqrt(3.0 / 7.0 - 2.0 / 7.0 * std::sqrt(1.2));
    const double b = std::sqrt(3.0 / 7.0 + 2.0 / 7.0 * std::sqrt(1.2));
    const double wa = (18.0 + std::sqrt(30.0)) / 36.0;
    const double wb = (18.0 - std::sqrt(30.0)) / 36.0;
    return {{-b, -a, a, b}, {wb, wa, wa, wb}};
  }
  default:
    throw std::invalid_argument("Gauss-Legendre rule with unsupported point count");
  }
}

// n-point Gauss rule on [0,1] for the weight (1-z)^2, from its moments mu_k = 2/((k+1)(k+2)(k+3)):
// the nodes are the roots of the degree-n orthogonal polynomial.
Rule1D gaussJacobi20(int n) {
  auto mu = [](int k) { return 2.0 / ((k + 1.0) * (k + 2.0) * (k + 3.0)); };
  Eigen::MatrixXd h(n, n);
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      h(i, j) = mu(i + j);
    }
    rhs[i] = -mu(i + n);
  }
  const Eigen::VectorXd c = h.fullPivLu().solve(rhs); // p(z) = z^n + sum c_j z^j
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (int i = 1; i < n; ++i) {
    companion(i, i - 1) = 1.0;
  }
  for (int i = 0; i < n; ++i) {
    companion(i, n - 1) = -c[i];
  }
  const Eigen::VectorXd roots = companion.eigenvalues().real();
  Eigen::MatrixXd v(n, n);
  Eigen::VectorXd m(n);
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < n; ++i) {
      v(k, i) = std::pow(roots[i], k);
    }
    m[k] = mu(k);
  }
  const Eigen::VectorXd w = v.fullPivLu().solve(m);
  Rule1D r;
  for (int i = 0; i < n; ++i) {
    r.x.push_back(roots[i]);
    r.w.push_back(w[i]);
  }
  return r;
}

QuadratureRule tensor(const std::string& name, int dim, int n) {
  const Rule1D g = gaussLegendre(n);
  QuadratureRule r{name, 2 * n - 1, {}, {}};
  const int nz = dim >= 3 ? n : 1;
  const int ny = dim >= 2 ? n : 1;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < n; ++i) {
        const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j),
                   uk = static_cast<std::size_t>(k);
        r.points.emplace_back(g.x[ui], dim >= 2 ? g.x[uj] : 0.0, dim >= 3 ? g.x[uk] : 0.0);
        r.weights.push_back(g.w[ui] * (dim >= 2 ? g.w[uj] : 1.0) * (dim >= 3 ? g.w[uk] : 1.0));
      }
    }
  }
  return r;
}

// Symmetric triangle rules on the unit triangle (area 1/2).
QuadratureRule triangleRule(int points) {
  QuadratureRule r;
  auto orbit3 = [&](double a, double w) { // (a, a), (1-2a, a), (a, 1-2a)
    r.points.emplace_back(a, a, 0.0);
    r.points.emplace_back(1.0 - 2.0 * a, a, 0.0);
    r.points.emplace_back(a, 1.0 - 2.0 * a, 0.0);
    for (int i = 0; i < 3; ++i) {
      r.weights.push_back(w);
    }
  };
  switch (points) {
  case 1:
    r = {"FPG1", 1, {Point(1.0 / 3.0, 1.0 / 3.0, 0.0)}, {0.5}};
    break;
  case 3:
    r = {"FPG3", 2, {}, {}};
    orbit3(1.0 / 6.0, 1.0 / 6.0);
    break;
  case 6: // Dunavant/Strang-Fix degree 4
    r = {"FPG6", 4, {}, {}};
    orbit3(0.445948490915965, 0.223381589678011 / 2.0);
    orbit3(0.091576213509771, 0.109951743655322 / 2.0);
    break;
  case 7: // Radon degree 5
    r = {"FPG7", 5, {Point(1.0 / 3.0, 1.0 / 3.0, 0.0)}, {0.225 / 2.0}};
    orbit3((6.0 - std::sqrt(15.0)) / 21.0, (155.0 - std::sqrt(15.0)) / 2400.0);
    orbit3((6.0 + std::sqrt(15.0)) / 21.0, (155.0 + std::sqrt(15.0)) / 2400.0);
    break;
  default:
    throw std::invalid_argument("unsupported triangle rule");
  }
  return r;
}

QuadratureRule tetraRule(int points) {
  switch (points) {
  case 1:
    return {"FPG1", 1, {Point(0.25, 0.25, 0.25)}, {1.0 / 6.0}};
  case 4: {
    const double a = (5.0 - std::sqrt(5.0)) / 20.0, b = (5.0 + 3.0 * std::sqrt(5.0)) / 20.0;
    return {"FPG4",
            2,
            {Point(a, a, a), Point(b, a, a), Point(a, b, a), Point(a, a, b)},
            {1.0 / 24.0, 1.0 / 24.0, 1.0 / 24.0, 1.0 / 24.0}};
  }
  case 5: {
    const double a = 1.0 / 6.0, b = 0.5, w = 3.0 / 40.0;
    return {"FPG5",
            3,
            {Point(0.25, 0.25, 0.25), Point(a, a, a), Point(b, a, a), Point(a, b, a), Point(a, a, b)},
            {-2.0 / 15.0, w, w, w, w}};
  }
  default:
    throw std::invalid_argument("unsupported tetrahedron rule");
  }
}

// Prism: triangle rule in (y, z) times Gauss-Legendre along the axis x.
QuadratureRule prismRule(const std::string& name, int trianglePoints, int linePoints) {
  const QuadratureRule t = triangleRule(trianglePoints);
  const Rule1D g = gaussLegendre(linePoints);
  QuadratureRule r{name, std::min(t.degree, 2 * linePoints - 1), {}, {}};
  for (std::size_t i = 0; i < g.x.size(); ++i) {
    for (int j = 0; j < t.size(); ++j) {
      const auto uj = static_cast<std::size_t>(j);
      r.points.emplace_back(g.x[i], t.points[uj][0], t.points[uj][1]);
      r.weights.push_back(g.w[i] * t.weights[uj]);
    }
  }
  return r;
}

QuadratureRule pyramidRule(int points) {
  if (points == 5) { // degree 2, code_aster's FPG5 of the pyramid
    const double h1 = 0.1531754163448146, h2 = 0.6372983346207416, w = 2.0 / 15.0;
    return {"FPG5",
            2,
            {Point(0.5, 0, h1), Point(0, 0.5, h1), Point(-0.5, 0, h1), Point(0, -0.5, h1), Point(0, 0, h2)},
            {w, w, w, w, w}};
  }
  if (points == 27) { // collapsed (conical) product: 3x3 Gauss on the square, Gauss-Jacobi in z
    const Rule1D g = gaussLegendre(3);
    const Rule1D j = gaussJacobi20(3);
    QuadratureRule r{"FPG27", 5, {}, {}};
    for (std::size_t k = 0; k < 3; ++k) {
      const double z = j.x[k], h = 1.0 - z;
      for (std::size_t b = 0; b < 3; ++b) {
        for (std::size_t a = 0; a < 3; ++a) {
          const double u = h * g.x[a], v = h * g.x[b]; // u = x + y, v = y - x
          r.points.emplace_back(0.5 * (u - v), 0.5 * (u + v), z);
          r.weights.push_back(0.5 * g.w[a] * g.w[b] * j.w[k]);
        }
      }
    }
    return r;
  }
  throw std::invalid_argument("unsupported pyramid rule");
}

int pointCount(const std::string& family) {
  return std::stoi(family.substr(3));
}

std::string rigiFamily(CellType type, IntegrationRole role) {
  const bool skin = role == IntegrationRole::Skin;
  switch (type) {
  case CellType::SEG2:
    return "FPG2";
  case CellType::SEG3:
    return skin ? "FPG4" : "FPG3";
  case CellType::TRIA3:
    return skin ? "FPG3" : "FPG1";
  case CellType::TRIA6:
    return (skin || role == IntegrationRole::AxisymmetricVolume) ? "FPG6" : "FPG3";
  case CellType::QUAD4:
    return "FPG4";
  case CellType::QUAD8:
  case CellType::QUAD9:
    return "FPG9";
  case CellType::TETRA4:
    return "FPG1";
  case CellType::TETRA10:
    return "FPG5";
  case CellType::PENTA6:
    return "FPG6";
  case CellType::PENTA15:
  case CellType::PENTA18:
    return "FPG21";
  case CellType::PYRAM5:
    return "FPG5";
  case CellType::PYRAM13:
    return "FPG27";
  case CellType::HEXA8:
    return "FPG8";
  case CellType::HEXA20:
  case CellType::HEXA27:
    return "FPG27";
  default:
    throw std::invalid_argument("no integration rule for cell type " + std::string(name(type)));
  }
}

} // namespace

QuadratureRule namedRule(CellType type, const std::string& family) {
  const int n = pointCount(family);
  switch (type) {
  case CellType::SEG2:
  case CellType::SEG3:
    return tensor(family, 1, n);
  case CellType::QUAD4:
  case CellType::QUAD8:
  case CellType::QUAD9:
    return tensor(family, 2, static_cast<int>(std::lround(std::sqrt(n))));
  case CellType::HEXA8:
  case CellType::HEXA20:
  case CellType::HEXA27:
    return tensor(family, 3, static_cast<int>(std::lround(std::cbrt(n))));
  case CellType::TRIA3:
  case CellType::TRIA6:
    return triangleRule(n);
  case CellType::TETRA4:
  case CellType::TETRA10:
    return tetraRule(n);
  case CellType::PENTA6:
  case CellType::PENTA15:
  case CellType::PENTA18:
    if (n == 6) {
      return prismRule("FPG6", 3, 2);
    }
    if (n == 21) {
      return prismRule("FPG21", 7, 3);
    }
    break;
  case CellType::PYRAM5:
  case CellType::PYRAM13:
    return pyramidRule(n);
  default:
    break;
  }
  throw std::invalid_argument("no rule " + family + " for cell type " + std::string(name(type)));
}

const QuadratureRule& rigiRule(CellType type, IntegrationRole role) {
  static std::array<std::array<std::unique_ptr<QuadratureRule>, integrationRoleCount>, cellTypeCount> cache;
  static std::array<std::array<std::once_flag, integrationRoleCount>, cellTypeCount> once;
  const auto i = static_cast<std::size_t>(type);
  const auto j = static_cast<std::size_t>(role);
  std::call_once(once[i][j], [&] {
    cache[i][j] = std::make_unique<QuadratureRule>(namedRule(type, rigiFamily(type, role)));
  });
  return *cache[i][j];
}

} // namespace stella::fem
