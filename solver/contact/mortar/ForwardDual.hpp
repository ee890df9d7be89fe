#pragma once
// A forward-mode dual number with N partial derivatives, for the geometric derivatives of the
// mortar integrals (LAC's consistent tangent, lac/LacOverlapTerms.hpp): the same templated code
// computes a value with T = double and the value and its gradient with T = ForwardDual<N>.
// Comparisons look at the value only (a branch taken is differentiated as it is: a clipped end has
// a zero derivative).

#include <array>
#include <cmath>

namespace stella::mortar {

template <int N> struct ForwardDual {
  double v = 0.0;
  std::array<double, N> d{};

  ForwardDual() = default;
  ForwardDual(double value) : v(value) {} // NOLINT(google-explicit-constructor): constants mix in
  static ForwardDual variable(double x, int i) {
    ForwardDual r(x);
    r.d[static_cast<std::size_t>(i)] = 1.0;
    return r;
  }

  ForwardDual& operator+=(const ForwardDual& b) {
    v += b.v;
    for (int i = 0; i < N; ++i) {
      d[i] += b.d[i];
    }
    return *this;
  }
  ForwardDual& operator-=(const ForwardDual& b) { return *this += -b; }
  ForwardDual& operator*=(const ForwardDual& b) { return *this = *this * b; }
  ForwardDual operator-() const {
    ForwardDual r(-v);
    for (int i = 0; i < N; ++i) {
      r.d[i] = -d[i];
    }
    return r;
  }

  friend ForwardDual operator+(ForwardDual a, const ForwardDual& b) { return a += b; }
  friend ForwardDual operator-(ForwardDual a, const ForwardDual& b) { return a += -b; }
  friend ForwardDual operator*(const ForwardDual& a, const ForwardDual& b) {
    ForwardDual r(a.v * b.v);
    for (int i = 0; i < N; ++i) {
      r.d[i] = a.d[i] * b.v + a.v * b.d[i];
    }
    return r;
  }
  friend ForwardDual operator/(const ForwardDual& a, const ForwardDual& b) {
    const double inv = 1.0 / b.v;
    const double q = a.v * inv;
    ForwardDual r(q);
    for (int i = 0; i < N; ++i) {
      r.d[i] = (a.d[i] - q * b.d[i]) * inv;
    }
    return r;
  }
  friend ForwardDual sqrt(const ForwardDual& a) {
    const double s = std::sqrt(a.v);
    ForwardDual r(s);
    for (int i = 0; i < N; ++i) {
      r.d[i] = a.d[i] / (2.0 * s);
    }
    return r;
  }
  friend ForwardDual abs(const ForwardDual& a) { return a.v < 0.0 ? -a : a; }
  friend bool operator<(const ForwardDual& a, const ForwardDual& b) { return a.v < b.v; }
  friend bool operator>(const ForwardDual& a, const ForwardDual& b) { return a.v > b.v; }
  friend bool operator<=(const ForwardDual& a, const ForwardDual& b) { return a.v <= b.v; }
  friend bool operator>=(const ForwardDual& a, const ForwardDual& b) { return a.v >= b.v; }
};

// The value of a double or a dual.
inline double valueOf(double x) {
  return x;
}
template <int N> double valueOf(const ForwardDual<N>& x) {
  return x.v;
}

} // namespace stella::mortar
