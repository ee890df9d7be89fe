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

} // namespace

Eigen::MatrixXd gapHessian(const CellNodes& master, int dim, const std::array<double, 2>& xi,
                           const Point3& slave, const Point3& normal) {
  CellPoint p;
  evaluateCell(master, xi, p);
  const int count = master.count;
  const int size = 3 * (1 + count);
  const std::array<Eigen::Vector3d, 2> tau{vec(p.d1), vec(p.d2)};
  Eigen::Vector3d n = dim == 1 ? Eigen::Vector3d(p.d1[1], -p.d1[0], 0.0) : tau[0].cross(tau[1]);
  n.normalize();
  if (n.dot(vec(normal)) < 0.0) {
    n = -n;
  }
  const double g = (vec(slave) - vec(p.x)).dot(n);
  const auto dd = secondDerivatives(master, dim, xi);
  Eigen::MatrixXd metric(dim, dim);
  Eigen::MatrixXd curvature(dim, dim);
  for (int a = 0; a < dim; ++a) {
    for (int b = 0; b < dim; ++b) {
      metric(a, b) = tau[static_cast<std::size_t>(a)].dot(tau[static_cast<std::size_t>(b)]);
      curvature(a, b) = n.dot(dd[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)]);
    }
  }
  // T_a = tau_a . (dx_s - sum_j N_j dx_j), P_a = n . sum_j dN_j/dxi_a dx_j
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(dim, size);
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(dim, size);
  for (int a = 0; a < dim; ++a) {
    const Eigen::Vector3d& ta = tau[static_cast<std::size_t>(a)];
    const auto& dn = a == 0 ? p.shape.dxi : p.shape.deta;
    t.block(a, 0, 1, 3) = ta.transpose();
    for (int j = 0; j < count; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      t.block(a, 3 * (1 + j), 1, 3) = -p.shape.n[jj] * ta.transpose();
      r.block(a, 3 * (1 + j), 1, 3) = dn[jj] * n.transpose();
    }
  }
  const Eigen::MatrixXd metricInverse = metric.inverse();
  const Eigen::MatrixXd projection = (metric - g * curvature).inverse(); // A^-1
  const Eigen::MatrixXd tt = metricInverse * curvature * projection;
  const Eigen::MatrixXd h = t.transpose() * tt * t + t.transpose() * projection * r +
                            r.transpose() * projection * t + g * r.transpose() * projection * r;
  return -0.5 * (h + h.transpose()); // symmetric up to round-off
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
