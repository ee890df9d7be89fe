#pragma once
// One 2D LAC overlap (a slave cell and a master cell, SEG2/SEG3) as a function of the current
// nodal positions, for any scalar T (LacPairing.hpp's symbols): the paired length L = sum w_q, the
// integrated gap G = sum w_q g_q, g_q = n_s . (x_m - x_s), the coefficients of the gap's gradient
// with the normals and overlaps held fixed c = sum w_q n_s (N_m, -N_s) (the LAC force direction,
// LacPatchRow::gradient) and of the slip sum w_q tau (N_s, -N_m). With T = double: the pairing's
// values; with T = LacDual seeded on the 12 local coordinates (slave nodes x, y, then master nodes
// x, y; LISSAGE: then the neighbouring slave nodes): their exact derivatives with respect to the nodal
// positions, through the overlap ends, the Gauss points, the normals, the master points and the Jacobians
// (ALGO_RESO_GEOM
// ='NEWTON' consistent tangent, LacGeometricTangent.cpp).

#include "solver/contact/mortar/ForwardDual.hpp"
#include "solver/contact/mortar/MortarSegmentKernel.hpp"

#include <array>
#include <span>

namespace stella::contact::lac {

inline constexpr int kOverlapCoordinates = 12; // 3 slave nodes + 3 master nodes, x and y
// LISSAGE: the averaged normals at the slave's nodes also depend on the other nodes of the
// neighbouring slave cells (at most 2 per end of a SEG3: 4 nodes), seeded after the 12.
inline constexpr int kNeighbourNodes = 4;
inline constexpr int kDerivativeCoordinates = kOverlapCoordinates + 2 * kNeighbourNodes;
using LacDual = mortar::ForwardDual<kDerivativeCoordinates>;

// The outward unit normal (sign (ty, -tx) / |t|) of a slave segment at xi.
template <class T>
mortar::kernel::Vec2<T> outwardNormal(CellType t, std::span<const mortar::kernel::Vec2<T>> nodes, double sign,
                                      double xi) {
  using std::sqrt;
  const mortar::kernel::Vec2<T> tan = mortar::kernel::tangent<T>(t, nodes, T(xi));
  const T j = sqrt(mortar::kernel::dot(tan, tan));
  return {sign * tan[1] / j, -sign * tan[0] / j};
}

template <class T> struct OverlapTerms {
  bool paired = false;
  T length{0.0};                               // L
  T gap{0.0};                                  // G
  std::array<T, kOverlapCoordinates> normal{}; // c, on the local coordinates
  std::array<T, kOverlapCoordinates> slip{};   // the slip coefficients, same layout
};

struct OverlapSetup {
  CellType slaveType = CellType::SEG2;
  CellType masterType = CellType::SEG2;
  double sign = 1.0;            // +1 when (ty, -tx) points out of the slave body
  bool axisymmetric = false;    // weights x r
  bool currentJacobian = false; // TYPE_JACOBIEN='ACTUALISE': |dx/dxi| of the current slave
  std::span<const double> gaussX, gaussW;
  double minLength = 1e-12;
  double grazingCosine = 1e-8;
};

// `slave`, `master`: current nodes; `initialSlave`: the slave's nodes in the mesh (the weights of
// TYPE_JACOBIEN='INITIAL'); `nodalNormals`: LISSAGE='OUI', the outward averaged normals at the
// slave's nodes (empty: the slave curve's normal). With them the normal at a point is
// n = sum N_i n_i / |sum N_i n_i|, for the overlap ends, the projections, the gaps and the force;
// with T = LacDual their derivatives come with them (LacSmoothing.hpp).
template <class T>
OverlapTerms<T> overlapTerms(const OverlapSetup& s, std::span<const mortar::kernel::Vec2<T>> slave,
                             std::span<const mortar::kernel::Vec2<T>> master,
                             std::span<const mortar::kernel::Vec2<double>> initialSlave,
                             std::span<const mortar::kernel::Vec2<T>> normals = {}) {
  namespace k = mortar::kernel;
  using std::sqrt;
  OverlapTerms<T> out;
  T a(0.0);
  T b(0.0);
  if (!k::coveredInterval<T>(s.slaveType, slave, s.masterType, master, s.minLength, s.grazingCosine, a, b,
                             normals)) {
    return out;
  }
  out.paired = true;
  for (std::size_t g = 0; g < s.gaussX.size(); ++g) {
    const T xi = 0.5 * (a + b) + 0.5 * (b - a) * s.gaussX[g];
    const k::Vec2<T> t = k::tangent<T>(s.slaveType, slave, xi);
    const T jt = sqrt(k::dot(t, t));
    k::Vec2<T> n = {s.sign * t[1] / jt, -s.sign * t[0] / jt};
    if (!normals.empty()) {
      const k::Vec2<T> field = k::normalField<T>(s.slaveType, normals, xi);
      const T length = sqrt(k::dot(field, field));
      n = {field[0] / length, field[1] / length};
    }
    const k::Vec2<T> xs = k::point<T>(s.slaveType, slave, xi);
    const T xiM = k::projectAlong<T>(s.masterType, master, xs, n);
    const k::Vec2<T> xm = k::point<T>(s.masterType, master, xiM);
    const T gap = n[0] * (xm[0] - xs[0]) + n[1] * (xm[1] - xs[1]);
    T measure(0.0);
    T r(0.0);
    if (s.currentJacobian) {
      measure = jt;
      r = xs[0];
    } else {
      // the initial Jacobian at the Gauss point, which moves with the overlap's ends
      std::array<k::Vec2<T>, 3> initial{};
      for (std::size_t i = 0; i < initialSlave.size(); ++i) {
        initial[i] = {T(initialSlave[i][0]), T(initialSlave[i][1])};
      }
      const std::span<const k::Vec2<T>> nodes(initial.data(), initialSlave.size());
      const k::Vec2<T> t0 = k::tangent<T>(s.slaveType, nodes, xi);
      measure = sqrt(k::dot(t0, t0));
      r = k::point<T>(s.slaveType, nodes, xi)[0];
    }
    const T w = s.gaussW[g] * 0.5 * (b - a) * (s.axisymmetric ? measure * r : measure);
    out.length += w;
    out.gap += w * gap;
    const k::Vec2<T> tau = {-n[1], n[0]};
    const auto ns = k::shape<T>(s.slaveType, xi);
    const auto nm = k::shape<T>(s.masterType, xiM);
    for (std::size_t i = 0; i < slave.size(); ++i) {
      for (std::size_t c = 0; c < 2; ++c) {
        out.normal[2 * i + c] -= w * ns.n[i] * n[c];
        out.slip[2 * i + c] += w * ns.n[i] * tau[c];
      }
    }
    for (std::size_t j = 0; j < master.size(); ++j) {
      for (std::size_t c = 0; c < 2; ++c) {
        out.normal[6 + 2 * j + c] += w * nm.n[j] * n[c];
        out.slip[6 + 2 * j + c] -= w * nm.n[j] * tau[c];
      }
    }
  }
  return out;
}

} // namespace stella::contact::lac
