// Closed-form shape functions of the contact surface cells (R3.01.01 orderings).

#include "solver/contact/SurfaceShape.hpp"

namespace stella::contact {

namespace {

// 1D quadratic Lagrange functions on nodes -1, 1, 0 (SEG3 order) and their derivatives.
void line2(double x, double* n, double* d) {
  n[0] = 0.5 * x * (x - 1.0);
  n[1] = 0.5 * x * (x + 1.0);
  n[2] = 1.0 - x * x;
  d[0] = x - 0.5;
  d[1] = x + 0.5;
  d[2] = -2.0 * x;
}

void quad4(double x, double y, SurfaceShapeValues& o) {
  const std::array<double, 4> sx{-1, 1, 1, -1};
  const std::array<double, 4> sy{-1, -1, 1, 1};
  for (std::size_t i = 0; i < 4; ++i) {
    const double fx = 1.0 + sx[i] * x;
    const double fy = 1.0 + sy[i] * y;
    o.n[i] = 0.25 * fx * fy;
    o.dxi[i] = 0.25 * sx[i] * fy;
    o.deta[i] = 0.25 * fx * sy[i];
  }
}

void quad8(double x, double y, SurfaceShapeValues& o) {
  const std::array<double, 4> sx{-1, 1, 1, -1};
  const std::array<double, 4> sy{-1, -1, 1, 1};
  for (std::size_t i = 0; i < 4; ++i) {
    const double fx = 1.0 + sx[i] * x;
    const double fy = 1.0 + sy[i] * y;
    const double g = sx[i] * x + sy[i] * y - 1.0;
    o.n[i] = 0.25 * fx * fy * g;
    o.dxi[i] = 0.25 * sx[i] * fy * (g + fx);
    o.deta[i] = 0.25 * sy[i] * fx * (g + fy);
  }
  // Mid-edge nodes of edges 01 (eta = -1), 12 (xi = 1), 23 (eta = 1), 30 (xi = -1).
  o.n[4] = 0.5 * (1.0 - x * x) * (1.0 - y);
  o.dxi[4] = -x * (1.0 - y);
  o.deta[4] = -0.5 * (1.0 - x * x);
  o.n[5] = 0.5 * (1.0 + x) * (1.0 - y * y);
  o.dxi[5] = 0.5 * (1.0 - y * y);
  o.deta[5] = -y * (1.0 + x);
  o.n[6] = 0.5 * (1.0 - x * x) * (1.0 + y);
  o.dxi[6] = -x * (1.0 + y);
  o.deta[6] = 0.5 * (1.0 - x * x);
  o.n[7] = 0.5 * (1.0 - x) * (1.0 - y * y);
  o.dxi[7] = -0.5 * (1.0 - y * y);
  o.deta[7] = -y * (1.0 - x);
}

void quad9(double x, double y, SurfaceShapeValues& o) {
  std::array<double, 3> nx{};
  std::array<double, 3> dx{};
  std::array<double, 3> ny{};
  std::array<double, 3> dy{};
  line2(x, nx.data(), dx.data());
  line2(y, ny.data(), dy.data());
  // (i, j) indices into the 1D functions (0: -1, 1: +1, 2: 0) for the 9 nodes in QUAD9 order.
  const std::array<int, 9> ix{0, 1, 1, 0, 2, 1, 2, 0, 2};
  const std::array<int, 9> iy{0, 0, 1, 1, 0, 2, 1, 2, 2};
  for (std::size_t k = 0; k < 9; ++k) {
    const auto a = static_cast<std::size_t>(ix[k]);
    const auto b = static_cast<std::size_t>(iy[k]);
    o.n[k] = nx[a] * ny[b];
    o.dxi[k] = dx[a] * ny[b];
    o.deta[k] = nx[a] * dy[b];
  }
}

void tria6(double x, double y, SurfaceShapeValues& o) {
  const double l = 1.0 - x - y;
  o.n = {l * (2.0 * l - 1.0), x * (2.0 * x - 1.0), y * (2.0 * y - 1.0),
         4.0 * x * l,         4.0 * x * y,         4.0 * y * l};
  o.dxi = {1.0 - 4.0 * l, 4.0 * x - 1.0, 0.0, 4.0 * (l - x), 4.0 * y, -4.0 * y};
  o.deta = {1.0 - 4.0 * l, 0.0, 4.0 * y - 1.0, -4.0 * x, 4.0 * x, 4.0 * (l - y)};
}

} // namespace

bool isSurfaceShape(CellType type) {
  switch (type) {
  case CellType::SEG2:
  case CellType::SEG3:
  case CellType::TRIA3:
  case CellType::TRIA6:
  case CellType::QUAD4:
  case CellType::QUAD8:
  case CellType::QUAD9:
    return true;
  default:
    return false;
  }
}

void surfaceShape(CellType type, double xi, double eta, SurfaceShapeValues& out) {
  out.n.fill(0.0);
  out.dxi.fill(0.0);
  out.deta.fill(0.0);
  switch (type) {
  case CellType::SEG2:
    out.count = 2;
    out.n[0] = 0.5 * (1.0 - xi);
    out.n[1] = 0.5 * (1.0 + xi);
    out.dxi[0] = -0.5;
    out.dxi[1] = 0.5;
    return;
  case CellType::SEG3:
    out.count = 3;
    line2(xi, out.n.data(), out.dxi.data());
    return;
  case CellType::TRIA3:
    out.count = 3;
    out.n[0] = 1.0 - xi - eta;
    out.n[1] = xi;
    out.n[2] = eta;
    out.dxi = {-1.0, 1.0, 0.0};
    out.deta = {-1.0, 0.0, 1.0};
    return;
  case CellType::TRIA6:
    out.count = 6;
    tria6(xi, eta, out);
    return;
  case CellType::QUAD4:
    out.count = 4;
    quad4(xi, eta, out);
    return;
  case CellType::QUAD8:
    out.count = 8;
    quad8(xi, eta, out);
    return;
  case CellType::QUAD9:
    out.count = 9;
    quad9(xi, eta, out);
    return;
  default:
    out.count = 0;
    return;
  }
}

double lebesgueBound(CellType type) {
  switch (type) {
  case CellType::SEG3:
    return 1.25;
  case CellType::TRIA6:
    return 5.0 / 3.0;
  case CellType::QUAD8:
    return 3.0; // at the centre: 4 x 1/4 + 4 x 1/2
  case CellType::QUAD9:
    return 1.5625;
  default:
    return 1.0;
  }
}

} // namespace stella::contact
