#include "solver/post/FrameChange.hpp"

#include "solver/mesh/MeshGeometry.hpp"

#include <cmath>
#include <numbers>

namespace stella {

namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;

Point3 row(const Rotation& r, int i) {
  return r[static_cast<std::size_t>(i)];
}

std::optional<Point3> unit(const Point3& v) {
  const double n = norm(v);
  if (n < 1.0e-12) {
    return std::nullopt;
  }
  return (1.0 / n) * v;
}

Rotation fromRows(const Point3& a, const Point3& b, const Point3& c) {
  return {a, b, c};
}

// R S R^T.
Matrix3 congruence(const Rotation& r, const Matrix3& s) {
  Matrix3 out{};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      double sum = 0.0;
      for (std::size_t k = 0; k < 3; ++k) {
        for (std::size_t l = 0; l < 3; ++l) {
          sum += r[i][k] * s[k][l] * r[j][l];
        }
      }
      out[i][j] = sum;
    }
  }
  return out;
}

void rotateTensor(FrameQuantity q, const Rotation& r, bool cylindrical, std::span<double> v) {
  const bool full = q == FrameQuantity::Tensor3D;
  const double xz = full ? v[4] : 0.0;
  const double yz = full ? v[5] : 0.0;
  const Matrix3 s{{{v[0], v[3], xz}, {v[3], v[1], yz}, {xz, yz, v[2]}}};
  const Matrix3 t = congruence(r, s);
  v[0] = t[0][0];
  v[1] = t[1][1];
  v[2] = t[2][2];
  if (full) {
    v[3] = t[0][1];
    v[4] = t[0][2];
    v[5] = t[1][2];
  } else {
    // code_aster's 2D cylindrical layout (rr, zz, theta theta, r theta).
    v[3] = cylindrical ? t[0][2] : t[0][1];
  }
}

} // namespace

std::optional<FrameQuantity> frameQuantity(std::string_view typeCham) {
  if (typeCham == "VECT_2D") {
    return FrameQuantity::Vector2D;
  }
  if (typeCham == "VECT_3D") {
    return FrameQuantity::Vector3D;
  }
  if (typeCham == "TENS_2D") {
    return FrameQuantity::Tensor2D;
  }
  if (typeCham == "TENS_3D") {
    return FrameQuantity::Tensor3D;
  }
  return std::nullopt;
}

int frameComponentCount(FrameQuantity q) {
  switch (q) {
  case FrameQuantity::Vector2D:
    return 2;
  case FrameQuantity::Vector3D:
    return 3;
  case FrameQuantity::Tensor2D:
    return 4;
  case FrameQuantity::Tensor3D:
    return 6;
  }
  return 0;
}

Rotation nauticalRotation(double alphaDegrees, double betaDegrees, double gammaDegrees) {
  const double k = std::numbers::pi / 180.0;
  const double ca = std::cos(alphaDegrees * k);
  const double sa = std::sin(alphaDegrees * k);
  const double cb = std::cos(betaDegrees * k);
  const double sb = std::sin(betaDegrees * k);
  const double cg = std::cos(gammaDegrees * k);
  const double sg = std::sin(gammaDegrees * k);
  return fromRows({cb * ca, cb * sa, -sb}, {sg * sb * ca - cg * sa, cg * ca + sg * sb * sa, sg * cb},
                  {sg * sa + cg * sb * ca, cg * sb * sa - sg * ca, cg * cb});
}

std::optional<Rotation> rotationFromVectors(const Point3& x, const Point3& y) {
  const auto ex = unit(x);
  if (!ex) {
    return std::nullopt;
  }
  const auto ey = unit(y - dot(y, *ex) * *ex);
  if (!ey) {
    return std::nullopt;
  }
  return fromRows(*ex, *ey, cross(*ex, *ey));
}

std::optional<Rotation> cylindricalRotation(const Point3& origin, const Point3& axis, const Point3& p) {
  const Point3 d = p - origin;
  const auto er = unit(d - dot(d, axis) * axis);
  if (!er) {
    return std::nullopt;
  }
  return fromRows(*er, axis, cross(axis, *er));
}

void rotateComponents(FrameQuantity q, const Rotation& r, bool cylindrical, std::span<double> v) {
  switch (q) {
  case FrameQuantity::Vector2D: {
    const Point3 g{v[0], v[1], 0.0};
    v[0] = dot(row(r, 0), g);
    v[1] = dot(row(r, cylindrical ? 2 : 1), g);
    return;
  }
  case FrameQuantity::Vector3D: {
    const Point3 g{v[0], v[1], v[2]};
    for (int i = 0; i < 3; ++i) {
      v[static_cast<std::size_t>(i)] = dot(row(r, i), g);
    }
    return;
  }
  case FrameQuantity::Tensor2D:
  case FrameQuantity::Tensor3D:
    rotateTensor(q, r, cylindrical, v);
    return;
  }
}

} // namespace stella
