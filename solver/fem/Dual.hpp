#pragma once
// A forward-mode dual number with three partial derivatives, used to build shape functions and
// their exact derivatives from one polynomial (or rational, for pyramids) expression.

#include <array>

namespace stella::fem {

struct Dual3 {
  double v = 0.0;
  std::array<double, 3> d{0.0, 0.0, 0.0};

  static Dual3 constant(double c) { return Dual3{c, {0.0, 0.0, 0.0}}; }
  static Dual3 variable(double x, int i) {
    Dual3 r{x, {0.0, 0.0, 0.0}};
    r.d[static_cast<std::size_t>(i)] = 1.0;
    return r;
  }
};

inline Dual3 operator+(const Dual3& a, const Dual3& b) {
  return {a.v + b.v, {a.d[0] + b.d[0], a.d[1] + b.d[1], a.d[2] + b.d[2]}};
}
inline Dual3 operator-(const Dual3& a, const Dual3& b) {
  return {a.v - b.v, {a.d[0] - b.d[0], a.d[1] - b.d[1], a.d[2] - b.d[2]}};
}
inline Dual3 operator*(const Dual3& a, const Dual3& b) {
  return {a.v * b.v, {a.d[0] * b.v + a.v * b.d[0], a.d[1] * b.v + a.v * b.d[1], a.d[2] * b.v + a.v * b.d[2]}};
}
inline Dual3 operator*(double s, const Dual3& a) {
  return {s * a.v, {s * a.d[0], s * a.d[1], s * a.d[2]}};
}
inline Dual3 operator/(const Dual3& a, const Dual3& b) {
  const double inv = 1.0 / b.v;
  const double q = a.v * inv;
  return {q, {(a.d[0] - q * b.d[0]) * inv, (a.d[1] - q * b.d[1]) * inv, (a.d[2] - q * b.d[2]) * inv}};
}

} // namespace stella::fem
