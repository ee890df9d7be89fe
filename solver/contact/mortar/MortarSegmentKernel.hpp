#pragma once
// The 2D mortar geometry of MortarSegments.hpp written once for any scalar T (double, or
// ForwardDual for the derivatives with respect to the nodal positions: LAC's consistent
// geometric tangent, lac/LacOverlapTerms.hpp): SEG2/SEG3 shape functions, points and tangents,
// the slave coordinate whose normal line passes through a point, the master coordinate on a line,
// and the slave interval a master covers.

#include "solver/mesh/CellType.hpp"

#include <array>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

namespace stella::mortar::kernel {

template <class T> using Vec2 = std::array<T, 2>;

// SEG2 / SEG3 (ends, then middle): values and d/dxi at xi.
template <class T> struct Shape {
  std::array<T, 3> n{};
  std::array<T, 3> d{};
};

template <class T> Shape<T> shape(CellType t, const T& xi) {
  if (t == CellType::SEG2) {
    return {{0.5 * (1.0 - xi), 0.5 * (1.0 + xi), T(0.0)}, {T(-0.5), T(0.5), T(0.0)}};
  }
  return {{-0.5 * xi * (1.0 - xi), 0.5 * xi * (1.0 + xi), 1.0 - xi * xi}, {xi - 0.5, xi + 0.5, -2.0 * xi}};
}

template <class T> T cross(const Vec2<T>& a, const Vec2<T>& b) {
  return a[0] * b[1] - a[1] * b[0];
}
template <class T> T dot(const Vec2<T>& a, const Vec2<T>& b) {
  return a[0] * b[0] + a[1] * b[1];
}
template <class T> Vec2<T> minus(const Vec2<T>& a, const Vec2<T>& b) {
  return {a[0] - b[0], a[1] - b[1]};
}

// x(xi) and dx/dxi of the segment of type `t` with `nodes` (2 or 3).
template <class T> Vec2<T> point(CellType t, std::span<const Vec2<T>> nodes, const T& xi) {
  const Shape<T> f = shape(t, xi);
  Vec2<T> x{T(0.0), T(0.0)};
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    x[0] += f.n[i] * nodes[i][0];
    x[1] += f.n[i] * nodes[i][1];
  }
  return x;
}
template <class T> Vec2<T> tangent(CellType t, std::span<const Vec2<T>> nodes, const T& xi) {
  const Shape<T> f = shape(t, xi);
  Vec2<T> x{T(0.0), T(0.0)};
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    x[0] += f.d[i] * nodes[i][0];
    x[1] += f.d[i] * nodes[i][1];
  }
  return x;
}

// The slave coordinate whose normal line passes through p: (p - x(xi)) . t(xi) = 0 (exact for a
// SEG2, Newton on the curve for a SEG3).
template <class T> T projectOnNormalLines(CellType t, std::span<const Vec2<T>> s, const Vec2<T>& p) {
  using std::abs;
  const Vec2<T> ab = minus(s[1], s[0]);
  T xi = 2.0 * dot(minus(p, s[0]), ab) / dot(ab, ab) - 1.0;
  if (t == CellType::SEG2) {
    return xi;
  }
  const Vec2<T> tt = {s[0][0] + s[1][0] - 2.0 * s[2][0], s[0][1] + s[1][1] - 2.0 * s[2][1]};
  for (int it = 0; it < 30; ++it) {
    const Vec2<T> r = minus(p, point(t, s, xi));
    const Vec2<T> tan = tangent(t, s, xi);
    const T step = dot(r, tan) / (dot(r, tt) - dot(tan, tan));
    xi -= step;
    if (abs(step) < 1e-15) {
      break;
    }
  }
  return xi;
}

// With normals given at the slave's nodes (LISSAGE: the averaged nodal normals), the normal field
// n(xi) = sum N_i(xi) n_i (not normalised: only its direction matters here), and the slave
// coordinate whose line along n(xi) passes through p: (p - x(xi)) x n(xi) = 0, by Newton from the
// geometric normal's answer.
template <class T> Vec2<T> normalField(CellType t, std::span<const Vec2<T>> normals, const T& xi) {
  return point(t, normals, xi);
}

template <class T>
T projectOnNormalField(CellType t, std::span<const Vec2<T>> s, std::span<const Vec2<T>> normals,
                       const Vec2<T>& p) {
  using std::abs;
  T xi = projectOnNormalLines(t, s, p);
  for (int it = 0; it < 30; ++it) {
    const Vec2<T> r = minus(p, point(t, s, xi));
    const T df = cross(r, tangent(t, normals, xi)) - cross(tangent(t, s, xi), normalField(t, normals, xi));
    const T step = cross(r, normalField(t, normals, xi)) / df;
    xi -= step;
    if (abs(step) < 1e-15) {
      break;
    }
  }
  return xi;
}

// The master coordinate where the line through x along n meets the master.
template <class T>
T projectAlong(CellType t, std::span<const Vec2<T>> m, const Vec2<T>& x, const Vec2<T>& n) {
  using std::abs;
  T xi(0.0);
  for (int it = 0; it < 30; ++it) {
    const T dg = cross(tangent(t, m, xi), n);
    if (!(dg < 0.0) && !(dg > 0.0)) {
      break;
    }
    const T step = cross(minus(point(t, m, xi), x), n) / dg;
    xi -= step;
    if (abs(step) < 1e-15) {
      break;
    }
  }
  return xi;
}

// The slave interval [a, b] of [-1, 1] that the master covers (the slave points whose normal lines
// pass through the master's ends, clipped; ends within `minLength` of a slave end snap to it);
// false when the master is seen edge-on (|cos| of the chords below `grazingCosine`) or the
// interval is shorter than 2 minLength.
// `normals`: the slave's nodal normals (LISSAGE), empty for the normals of the slave curve.
template <class T>
bool coveredInterval(CellType slaveType, std::span<const Vec2<T>> slave, CellType masterType,
                     std::span<const Vec2<T>> master, double minLength, double grazingCosine, T& a, T& b,
                     std::span<const Vec2<T>> normals = {}) {
  using std::abs;
  using std::sqrt;
  (void)masterType;
  const double eps = 2 * minLength;
  const Vec2<T> slaveChord = minus(slave[1], slave[0]);
  const Vec2<T> chord = minus(master[1], master[0]);
  const T cosine = abs(dot(chord, slaveChord)) / sqrt(dot(chord, chord) * dot(slaveChord, slaveChord));
  if (!(cosine >= grazingCosine)) {
    return false; // master seen edge-on (or degenerate)
  }
  a = normals.empty() ? projectOnNormalLines(slaveType, slave, master[0])
                      : projectOnNormalField(slaveType, slave, normals, master[0]);
  b = normals.empty() ? projectOnNormalLines(slaveType, slave, master[1])
                      : projectOnNormalField(slaveType, slave, normals, master[1]);
  if (a > b) {
    std::swap(a, b);
  }
  a = abs(a + 1.0) <= eps ? T(-1.0) : (a < -1.0 ? T(-1.0) : a);
  b = abs(b - 1.0) <= eps ? T(1.0) : (b > 1.0 ? T(1.0) : b);
  return b - a > eps;
}

// Gauss-Legendre points and weights on [-1, 1] (1 to 4 points; more: 4).
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w);

} // namespace stella::mortar::kernel
