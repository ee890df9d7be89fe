// The second derivative of the node-to-surface gap (ALGO_RESO_GEOM='NEWTON'), and its place in the
// tangent of the continuous formulation.

#include "solver/contact/ContinuousGeometricTangent.hpp"
#include "solver/contact/ContinuousContactConstraint.hpp"

#include "solver/mesh/MeshGeometry.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella::contact {

namespace {

Eigen::Vector3d vec(const Point3& p) {
  return {p[0], p[1], p[2]};
}

// Step of the central differences giving d2x_m/dxi_a dxi_b from dx_m/dxi_a: the surface cells'
// shape functions are of degree <= 2 in each parametric coordinate, so their first derivatives are
// of degree <= 2 along each coordinate and the central difference is exact for any step (no
// truncation); a large one keeps the round-off small.
constexpr double secondDerivativeStep = 0.5;

// d2x_m / dxi_a dxi_b (a, b < dim), symmetrised.
std::array<std::array<Eigen::Vector3d, 2>, 2> secondDerivatives(const CellNodes& master, int dim,
                                                                const std::array<double, 2>& xi) {
  std::array<std::array<Eigen::Vector3d, 2>, 2> d{};
  CellPoint plus;
  CellPoint minus;
  for (int b = 0; b < dim; ++b) {
    std::array<double, 2> xp = xi;
    std::array<double, 2> xm = xi;
    xp[static_cast<std::size_t>(b)] += secondDerivativeStep;
    xm[static_cast<std::size_t>(b)] -= secondDerivativeStep;
    evaluateCell(master, xp, plus);
    evaluateCell(master, xm, minus);
    const double h = 2.0 * secondDerivativeStep;
    d[0][static_cast<std::size_t>(b)] = (vec(plus.d1) - vec(minus.d1)) / h;
    d[1][static_cast<std::size_t>(b)] = (vec(plus.d2) - vec(minus.d2)) / h;
  }
  if (dim == 2) {
    const Eigen::Vector3d mixed = 0.5 * (d[0][1] + d[1][0]);
    d[0][1] = mixed;
    d[1][0] = mixed;
  }
  return d;
}

// The first-order quantities of the projection of a slave point on a master cell (the header's
// notation): the covariant tangents, the unit normal, the gap, the metric and curvature, the rows
// T_a and P_a over (x_s, x_1 .. x_n) and A^-1.
struct ProjectionLinearisation {
  CellPoint p;
  int dim = 1;
  int size = 0;
  std::array<Eigen::Vector3d, 2> tau;
  Eigen::Vector3d n;
  double g = 0.0;
  std::array<std::array<Eigen::Vector3d, 2>, 2> dd{};
  Eigen::MatrixXd metric;
  Eigen::MatrixXd curvature;
  Eigen::MatrixXd t;          // T_a = tau_a . (dx_s - sum_j N_j dx_j)
  Eigen::MatrixXd r;          // P_a = n . sum_j dN_j/dxi_a dx_j
  Eigen::MatrixXd projection; // A^-1 = (a - g k)^-1
};

ProjectionLinearisation linearise(const CellNodes& master, int dim, const std::array<double, 2>& xi,
                                  const Point3& slave, const Point3& normal) {
  ProjectionLinearisation l;
  evaluateCell(master, xi, l.p);
  const CellPoint& p = l.p;
  const int count = master.count;
  l.dim = dim;
  l.size = 3 * (1 + count);
  l.tau = {vec(p.d1), vec(p.d2)};
  l.n = dim == 1 ? Eigen::Vector3d(p.d1[1], -p.d1[0], 0.0) : l.tau[0].cross(l.tau[1]);
  l.n.normalize();
  if (l.n.dot(vec(normal)) < 0.0) {
    l.n = -l.n;
  }
  l.g = (vec(slave) - vec(p.x)).dot(l.n);
  l.dd = secondDerivatives(master, dim, xi);
  l.metric.resize(dim, dim);
  l.curvature.resize(dim, dim);
  for (int a = 0; a < dim; ++a) {
    for (int b = 0; b < dim; ++b) {
      l.metric(a, b) = l.tau[static_cast<std::size_t>(a)].dot(l.tau[static_cast<std::size_t>(b)]);
      l.curvature(a, b) = l.n.dot(l.dd[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)]);
    }
  }
  l.t = Eigen::MatrixXd::Zero(dim, l.size);
  l.r = Eigen::MatrixXd::Zero(dim, l.size);
  for (int a = 0; a < dim; ++a) {
    const Eigen::Vector3d& ta = l.tau[static_cast<std::size_t>(a)];
    const auto& dn = a == 0 ? p.shape.dxi : p.shape.deta;
    l.t.block(a, 0, 1, 3) = ta.transpose();
    for (int j = 0; j < count; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      l.t.block(a, 3 * (1 + j), 1, 3) = -p.shape.n[jj] * ta.transpose();
      l.r.block(a, 3 * (1 + j), 1, 3) = dn[jj] * l.n.transpose();
    }
  }
  l.projection = (l.metric - l.g * l.curvature).inverse();
  return l;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v(2), v(1), v(2), 0.0, -v(0), -v(1), v(0), 0.0;
  return s;
}

} // namespace

Eigen::MatrixXd gapHessian(const CellNodes& master, int dim, const std::array<double, 2>& xi,
                           const Point3& slave, const Point3& normal) {
  const ProjectionLinearisation l = linearise(master, dim, xi, slave, normal);
  const Eigen::MatrixXd metricInverse = l.metric.inverse();
  const Eigen::MatrixXd tt = metricInverse * l.curvature * l.projection;
  const Eigen::MatrixXd h = l.t.transpose() * tt * l.t + l.t.transpose() * l.projection * l.r +
                            l.r.transpose() * l.projection * l.t + l.g * l.r.transpose() * l.projection * l.r;
  return -0.5 * (h + h.transpose()); // symmetric up to round-off
}

std::array<Eigen::MatrixXd, 2> frictionRowJacobians(const CellNodes& master, int dim,
                                                    const std::array<double, 2>& xi, const Point3& slave,
                                                    const Point3& normal, const Point3& tangent1) {
  const ProjectionLinearisation l = linearise(master, dim, xi, slave, normal);
  const int count = master.count;
  // dxi = A^-1 (T + g P); dtau_a = sum_j dN_j/dxi_a dx_j + sum_b d2x_m/dxi_a dxi_b dxi_b
  const Eigen::MatrixXd dxi = l.projection * (l.t + l.g * l.r);
  std::array<Eigen::MatrixXd, 2> dtau;
  for (int a = 0; a < dim; ++a) {
    const auto aa = static_cast<std::size_t>(a);
    const auto& dn = a == 0 ? l.p.shape.dxi : l.p.shape.deta;
    dtau[aa] = Eigen::MatrixXd::Zero(3, l.size);
    for (int j = 0; j < count; ++j) {
      dtau[aa].block(0, 3 * (1 + j), 3, 3) = dn[static_cast<std::size_t>(j)] * Eigen::Matrix3d::Identity();
    }
    for (int b = 0; b < dim; ++b) {
      dtau[aa] += l.dd[aa][static_cast<std::size_t>(b)] * dxi.row(b);
    }
  }
  // t_1 = +-tau_1 / |tau_1| (oriented as the pairing's), t_2 = n x t_1 (3D)
  const double length = l.tau[0].norm();
  Eigen::Vector3d t1 = l.tau[0] / length;
  const double sense = t1.dot(vec(tangent1)) < 0.0 ? -1.0 : 1.0;
  t1 *= sense;
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  std::array<Eigen::Vector3d, 2> t{t1, Eigen::Vector3d::Zero()};
  std::array<Eigen::MatrixXd, 2> dt;
  dt[0] = sense * (identity - t1 * t1.transpose()) * dtau[0] / length;
  dt[1] = Eigen::MatrixXd::Zero(3, l.size);
  if (dim == 2) {
    // n = c / |c| (oriented), c = tau_1 x tau_2: dn = (I - n n^T) dc / |c|
    const Eigen::Vector3d c = l.tau[0].cross(l.tau[1]);
    const double orientation = c.dot(l.n) < 0.0 ? -1.0 : 1.0;
    const Eigen::MatrixXd dc = skew(l.tau[0]) * dtau[1] - skew(l.tau[1]) * dtau[0];
    const Eigen::MatrixXd dn = orientation * (identity - l.n * l.n.transpose()) * dc / c.norm();
    t[1] = l.n.cross(t1);
    dt[1] = skew(l.n) * dt[0] - skew(t1) * dn;
  }
  // row T_j = (t_j on the slave, -N_k t_j on master node k); its Jacobian over the positions
  std::array<Eigen::MatrixXd, 2> m;
  for (std::size_t j = 0; j < 2; ++j) {
    m[j] = Eigen::MatrixXd::Zero(l.size, l.size);
    if (j == 1 && dim == 1) {
      continue;
    }
    m[j].block(0, 0, 3, l.size) = dt[j];
    for (int k = 0; k < count; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      Eigen::RowVectorXd dnk = l.p.shape.dxi[kk] * dxi.row(0);
      if (dim == 2) {
        dnk += l.p.shape.deta[kk] * dxi.row(1);
      }
      m[j].block(3 * (1 + k), 0, 3, l.size) = -l.p.shape.n[kk] * dt[j] - t[j] * dnk;
    }
  }
  return m;
}

Eigen::MatrixXd gapHessian(const Mesh& mesh, const NodePosition& position, const ContactLink& link) {
  CellNodes cell;
  cell.type = mesh.cellType(link.masterCell);
  const auto nodes = mesh.cellNodes(link.masterCell);
  cell.count = static_cast<int>(nodes.size());
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    cell.x[j] = position(nodes[j]);
  }
  return gapHessian(cell, info(cell.type).dimension, link.xi, position(link.slave), link.normal);
}

bool ContinuousContactConstraint::geometryNewton() const {
  return definition_->settings.continuous.geometryNewton;
}

void ContinuousContactConstraint::pairInNewton(const Eigen::VectorXd& u) {
  if (!geometryNewton()) {
    noteGeometry_ = geometricCriterion(u);
    return;
  }
  if (u.size() == uPairing_.size() && u == uPairing_) {
    return; // paired here already (the residual and the forces of one iteration)
  }
  // the change since the last pairing: the last correction, what RESI_GEOM bounds
  noteGeometry_ = geometricCriterion(u);
  pairAgain(u);
}

bool ContinuousContactConstraint::geometryConverged() {
  if (!geometryNewton() || noteGeometry_ <= definition_->settings.geometricResidual) {
    return true;
  }
  continuation_ = fmt::format("ALGO_RESO_GEOM='NEWTON': the contact nodes moved by {:.3e} of the step's "
                              "displacement at the last iteration (RESI_GEOM = {}): Newton iterations go on",
                              noteGeometry_, definition_->settings.geometricResidual);
  return false;
}

void ContinuousContactConstraint::addGeometricTangent(Eigen::Index row, double coefficient,
                                                      const NodePosition& position,
                                                      std::vector<Eigen::Triplet<double>>& tangent) const {
  const ContactLink& link = links_[static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)])];
  if (link.masterCell < 0) {
    return;
  }
  const Mesh& mesh = *definition_->mesh;
  const Eigen::MatrixXd h = gapHessian(mesh, position, link);
  const auto masters = mesh.cellNodes(link.masterCell);
  const auto nodes = static_cast<int>(masters.size()) + 1;
  const int components = dofs_.components();
  auto dofOf = [&](int node, int c) {
    return dofs_.dof(node == 0 ? link.slave : masters[static_cast<std::size_t>(node - 1)], c);
  };
  for (int a = 0; a < nodes; ++a) {
    for (int ca = 0; ca < components; ++ca) {
      const int p = dofOf(a, ca);
      if (p < 0) {
        continue;
      }
      for (int b = 0; b < nodes; ++b) {
        for (int cb = 0; cb < components; ++cb) {
          const int q = dofOf(b, cb);
          if (q >= 0) {
            tangent.emplace_back(p, q, coefficient * h(3 * a + ca, 3 * b + cb));
          }
        }
      }
    }
  }
}

} // namespace stella::contact
