// Tests of the reference elements and Gauss rules: Kronecker property, partition of unity,
// derivatives against finite differences, exact integration of monomials up to each rule's
// degree, and the volume of a distorted cell.

#include "solver/fem/ReferenceElement.hpp"
#include "solver/fem/Quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella::fem {
namespace {

const CellType allTypes[] = {CellType::SEG2,    CellType::SEG3,    CellType::TRIA3,   CellType::TRIA6,
                             CellType::QUAD4,   CellType::QUAD8,   CellType::QUAD9,   CellType::TETRA4,
                             CellType::TETRA10, CellType::PENTA6,  CellType::PENTA15, CellType::PENTA18,
                             CellType::PYRAM5,  CellType::PYRAM13, CellType::HEXA8,   CellType::HEXA20,
                             CellType::HEXA27};

// A point strictly inside each reference shape.
Eigen::Vector3d interiorPoint(CellType t, int k) {
  const double s = 0.07 * (k + 1);
  switch (dimension(t)) {
  case 1:
    return {-0.6 + s, 0, 0};
  case 2:
    if (t == CellType::TRIA3 || t == CellType::TRIA6) {
      return {0.1 + 0.5 * s, 0.2 + 0.3 * s, 0};
    }
    return {-0.6 + s, 0.3 - s, 0};
  default:
    break;
  }
  if (t == CellType::TETRA4 || t == CellType::TETRA10) {
    return {0.1 + 0.3 * s, 0.2, 0.15 + 0.2 * s};
  }
  if (t == CellType::PENTA6 || t == CellType::PENTA15 || t == CellType::PENTA18) {
    return {-0.6 + s, 0.2 + 0.2 * s, 0.3};
  }
  if (t == CellType::PYRAM5 || t == CellType::PYRAM13) {
    return {0.2 - 0.3 * s, 0.1 + 0.2 * s, 0.3 + 0.1 * s};
  }
  return {-0.6 + s, 0.3 - s, 0.5 - 0.5 * s};
}

TEST(ReferenceElement, KroneckerAtNodes) {
  for (CellType t : allTypes) {
    const auto& e = referenceElement(t);
    ASSERT_EQ(e.nodeCount(), nodeCount(t)) << name(t);
    for (int i = 0; i < e.nodeCount(); ++i) {
      const Eigen::VectorXd n = e.values(e.node(i));
      for (int j = 0; j < e.nodeCount(); ++j) {
        EXPECT_NEAR(n[j], i == j ? 1.0 : 0.0, 1e-12) << name(t) << " node " << i << " fn " << j;
      }
    }
  }
}

TEST(ReferenceElement, PartitionOfUnityAndReproducesCoordinates) {
  for (CellType t : allTypes) {
    const auto& e = referenceElement(t);
    for (int k = 0; k < 5; ++k) {
      const Eigen::Vector3d xi = interiorPoint(t, k);
      const Eigen::VectorXd n = e.values(xi);
      const Eigen::MatrixXd g = e.gradients(xi);
      EXPECT_NEAR(n.sum(), 1.0, 1e-13) << name(t);
      for (int d = 0; d < e.dimension(); ++d) {
        EXPECT_NEAR(g.col(d).sum(), 0.0, 1e-12) << name(t);
        double x = 0.0;
        for (int i = 0; i < e.nodeCount(); ++i) {
          x += n[i] * e.node(i)[d];
        }
        EXPECT_NEAR(x, xi[d], 1e-13) << name(t) << " linear completeness";
      }
    }
  }
}

TEST(ReferenceElement, DerivativesMatchFiniteDifferences) {
  const double h = 1e-6;
  for (CellType t : allTypes) {
    const auto& e = referenceElement(t);
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d xi = interiorPoint(t, k);
      const Eigen::MatrixXd g = e.gradients(xi);
      for (int d = 0; d < e.dimension(); ++d) {
        Eigen::Vector3d p = xi, m = xi;
        p[d] += h;
        m[d] -= h;
        const Eigen::VectorXd fd = (e.values(p) - e.values(m)) / (2 * h);
        EXPECT_LT((fd - g.col(d)).cwiseAbs().maxCoeff(), 1e-8) << name(t) << " d" << d;
      }
    }
  }
}

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

// Exact integral of x^a y^b z^c over each reference shape, from closed forms.
double exactMonomialIntegral(CellType t, int a, int b, int c) {
  auto segment = [](int p) { return p % 2 == 1 ? 0.0 : 2.0 / (p + 1); };
  const int dim = dimension(t);
  if (t == CellType::SEG2 || t == CellType::SEG3 || t == CellType::QUAD4 || t == CellType::QUAD8 ||
      t == CellType::QUAD9 || t == CellType::HEXA8 || t == CellType::HEXA20 || t == CellType::HEXA27) {
    return segment(a) * (dim >= 2 ? segment(b) : 1.0) * (dim >= 3 ? segment(c) : 1.0);
  }
  if (t == CellType::TRIA3 || t == CellType::TRIA6) {
    return factorial(a) * factorial(b) / factorial(a + b + 2);
  }
  if (t == CellType::TETRA4 || t == CellType::TETRA10) {
    return factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3);
  }
  if (t == CellType::PENTA6 || t == CellType::PENTA15 || t == CellType::PENTA18) {
    return segment(a) * factorial(b) * factorial(c) / factorial(b + c + 2);
  }
  // pyramid |x| + |y| <= 1 - z, 0 <= z <= 1
  if (a % 2 == 1 || b % 2 == 1) {
    return 0.0;
  }
  return 4.0 * factorial(a) * factorial(b) * factorial(c) / factorial(a + b + c + 3);
}

void checkRule(CellType t, const QuadratureRule& r) {
  const int dim = dimension(t);
  double sum = 0.0;
  for (double w : r.weights) {
    sum += w;
  }
  EXPECT_NEAR(sum, referenceElement(t).measure(), 1e-13) << name(t) << " " << r.name;
  for (int a = 0; a <= r.degree; ++a) {
    for (int b = 0; b <= (dim >= 2 ? r.degree - a : 0); ++b) {
      for (int c = 0; c <= (dim >= 3 ? r.degree - a - b : 0); ++c) {
        double q = 0.0;
        for (int i = 0; i < r.size(); ++i) {
          const auto& p = r.points[static_cast<std::size_t>(i)];
          q += r.weights[static_cast<std::size_t>(i)] * std::pow(p[0], a) * std::pow(p[1], b) *
               std::pow(p[2], c);
        }
        EXPECT_NEAR(q, exactMonomialIntegral(t, a, b, c), 1e-13)
            << name(t) << " " << r.name << " x^" << a << " y^" << b << " z^" << c;
      }
    }
  }
}

TEST(Quadrature, RigiRulesIntegrateMonomialsOfTheirDegree) {
  for (CellType t : allTypes) {
    checkRule(t, rigiRule(t, IntegrationRole::Volume));
    if (dimension(t) <= 2) {
      checkRule(t, rigiRule(t, IntegrationRole::Skin));
    }
  }
  checkRule(CellType::TETRA10, namedRule(CellType::TETRA10, "FPG4"));
  checkRule(CellType::TRIA6, namedRule(CellType::TRIA6, "FPG7"));
}

TEST(Quadrature, PointCountsAreCodeAsters) {
  struct Expect {
    CellType t;
    int volume;
  };
  const Expect table[] = {{CellType::TRIA3, 1},    {CellType::TRIA6, 3},   {CellType::QUAD4, 4},
                          {CellType::QUAD8, 9},    {CellType::QUAD9, 9},   {CellType::TETRA4, 1},
                          {CellType::TETRA10, 5},  {CellType::PENTA6, 6},  {CellType::PENTA15, 21},
                          {CellType::PENTA18, 21}, {CellType::PYRAM5, 5},  {CellType::PYRAM13, 27},
                          {CellType::HEXA8, 8},    {CellType::HEXA20, 27}, {CellType::HEXA27, 27}};
  for (const auto& e : table) {
    EXPECT_EQ(rigiRule(e.t, IntegrationRole::Volume).size(), e.volume) << name(e.t);
  }
  EXPECT_EQ(rigiRule(CellType::SEG2, IntegrationRole::Skin).size(), 2);
  EXPECT_EQ(rigiRule(CellType::SEG3, IntegrationRole::Skin).size(), 4);
  EXPECT_EQ(rigiRule(CellType::TRIA3, IntegrationRole::Skin).size(), 3);
  EXPECT_EQ(rigiRule(CellType::TRIA6, IntegrationRole::Skin).size(), 6);
  EXPECT_EQ(rigiRule(CellType::QUAD8, IntegrationRole::Skin).size(), 9);
}

// Volume of a cell whose nodes are the reference nodes mapped by x -> A x + b plus a quadratic
// term: the isoparametric volume integral must equal the exact volume of the mapped shape.
TEST(ReferenceElement, VolumeOfDistortedCell) {
  for (CellType t : allTypes) {
    const auto& e = referenceElement(t);
    const int dim = e.dimension();
    Eigen::Matrix3d a;
    a << 1.3, 0.2, -0.1, 0.1, 0.9, 0.3, -0.2, 0.1, 1.1;
    const Eigen::MatrixXd aa = a.topLeftCorner(dim, dim);
    // affine map: exact volume = |det A| * reference measure, for every element type
    const QuadratureRule& r = rigiRule(t, IntegrationRole::Volume);
    double v = 0.0;
    for (int q = 0; q < r.size(); ++q) {
      const Eigen::MatrixXd g = e.gradients(r.points[static_cast<std::size_t>(q)]);
      Eigen::MatrixXd x(e.nodeCount(), dim);
      for (int i = 0; i < e.nodeCount(); ++i) {
        x.row(i) = (aa * e.node(i).head(dim)).transpose();
      }
      const Eigen::MatrixXd jac = x.transpose() * g;
      v += r.weights[static_cast<std::size_t>(q)] * jac.determinant();
    }
    EXPECT_NEAR(v, aa.determinant() * e.measure(), 1e-12) << name(t);
  }
  // a curved QUAD8: the parabola edge y = 1 + 0.2 (1 - x^2) on top of [-1,1]^2 has area 4 + 0.8/3
  const auto& q8 = referenceElement(CellType::QUAD8);
  Eigen::MatrixXd x(8, 2);
  for (int i = 0; i < 8; ++i) {
    x.row(i) = q8.node(i).head(2).transpose();
  }
  x(6, 1) = 1.2; // mid-node of the top edge
  const QuadratureRule& r = rigiRule(CellType::QUAD8, IntegrationRole::Volume);
  double area = 0.0;
  for (int q = 0; q < r.size(); ++q) {
    const Eigen::MatrixXd jac = x.transpose() * q8.gradients(r.points[static_cast<std::size_t>(q)]);
    area += r.weights[static_cast<std::size_t>(q)] * jac.determinant();
  }
  EXPECT_NEAR(area, 4.0 + 0.8 / 3.0, 1e-13);
}

} // namespace
} // namespace stella::fem
