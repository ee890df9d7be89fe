// RigidRelations: LIAISON_SOLIDE relations for small rotations (see the header for the scheme).

#include "solver/model/RigidRelations.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

namespace stella {

namespace {

Eigen::Vector3d position(const Mesh& mesh, NodeId n) {
  const Point3 p = mesh.point(n);
  return {p[0], p[1], p[2]};
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s; // s w = v x w
}

// A relation sum over (node, component) of coefficients = 0, built term by term.
class RelationBuilder {
public:
  void add(NodeId n, int c, double coefficient) { terms_[{n, c}] += coefficient; }
  LinearRelation finish(double scale) const {
    LinearRelation r;
    r.origin = "LIAISON_SOLIDE";
    for (const auto& [key, coefficient] : terms_) {
      if (std::fabs(coefficient) > 1.0e-13 * scale) {
        r.terms.push_back({key.first, key.second, coefficient});
      }
    }
    return r;
  }

private:
  std::map<std::pair<NodeId, int>, double> terms_;
};

// theta = sum over the reference nodes of G_k u_k (3 x 3 blocks; 2D uses row z and columns x, y).
struct RotationOperator {
  std::vector<NodeId> nodes;
  std::vector<Eigen::Matrix3d> blocks;
};

// From the relative displacements d_k = u_k - u_A = theta x r_k (k = B, C), least squares:
// (sum |r_k|^2 I - r_k r_k^T) theta = sum r_k x d_k. `collinear`: only B, and the component of
// theta along AB is left out (pseudo-inverse), as it moves no node of the set.
RotationOperator rotationOperator(NodeId a, const std::vector<NodeId>& refs,
                                  const std::vector<Eigen::Vector3d>& r) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  for (const auto& v : r) {
    m += v.squaredNorm() * Eigen::Matrix3d::Identity() - v * v.transpose();
  }
  Eigen::Matrix3d inverse;
  if (r.size() == 1) { // M = |b|^2 (I - e e^T): pseudo-inverse (I - e e^T) / |b|^2
    const Eigen::Vector3d e = r[0].normalized();
    inverse = (Eigen::Matrix3d::Identity() - e * e.transpose()) / r[0].squaredNorm();
  } else {
    inverse = m.inverse();
  }
  RotationOperator op;
  op.nodes.push_back(a);
  op.blocks.push_back(Eigen::Matrix3d::Zero());
  for (std::size_t k = 0; k < refs.size(); ++k) {
    const Eigen::Matrix3d g = inverse * skew(r[k]);
    op.nodes.push_back(refs[k]);
    op.blocks.push_back(g);
    op.blocks[0] -= g;
  }
  return op;
}

// Distance kept to first order: (u_q - u_p) . (x_q - x_p) = 0.
LinearRelation distanceRelation(const Mesh& mesh, NodeId p, NodeId q, int dim, double scale) {
  const Eigen::Vector3d d = position(mesh, q) - position(mesh, p);
  RelationBuilder b;
  for (int c = 0; c < dim; ++c) {
    b.add(q, c, d(c));
    b.add(p, c, -d(c));
  }
  return b.finish(scale);
}

// u_M - u_A - theta x AM = 0, i.e. u_M - u_A + [AM]x theta = 0, one relation per component.
void followRelations(const Mesh& mesh, NodeId a, NodeId m, const RotationOperator& op, int dim, double scale,
                     std::vector<LinearRelation>& out) {
  const Eigen::Matrix3d s = skew(position(mesh, m) - position(mesh, a));
  for (int i = 0; i < dim; ++i) {
    RelationBuilder b;
    b.add(m, i, 1.0);
    b.add(a, i, -1.0);
    for (std::size_t k = 0; k < op.nodes.size(); ++k) {
      const Eigen::Matrix3d g = s * op.blocks[k];
      for (int j = 0; j < dim; ++j) {
        b.add(op.nodes[k], j, g(i, j));
      }
    }
    out.push_back(b.finish(scale));
  }
}

} // namespace

std::vector<LinearRelation> rigidBodyRelations(const Mesh& mesh, std::span<const NodeId> nodes, int dim,
                                               double distMin) {
  std::vector<LinearRelation> out;
  if (nodes.size() < 2) {
    return out;
  }
  const NodeId a = nodes[0];
  const Eigen::Vector3d xa = position(mesh, a);
  NodeId b = a;
  double farthest = 0.0;
  for (NodeId n : nodes) {
    const double d = (position(mesh, n) - xa).norm();
    if (d > farthest) {
      farthest = d;
      b = n;
    }
  }
  const double tolerance = distMin > 0.0 ? distMin : 1.0e-8 * farthest;
  const double scale = 1.0;    // coefficients are O(1): 1 for u, O(1) for theta x AM
  if (farthest <= tolerance) { // all coincident: every node follows A
    for (NodeId m : nodes) {
      for (int c = 0; c < dim && m != a; ++c) {
        out.push_back({{{m, c, 1.0}, {a, c, -1.0}}, 0.0, "LIAISON_SOLIDE"});
      }
    }
    return out;
  }
  const Eigen::Vector3d ab = position(mesh, b) - xa;
  std::vector<NodeId> refs{b};
  std::vector<Eigen::Vector3d> r{ab};
  out.push_back(distanceRelation(mesh, a, b, dim, scale));
  if (dim == 3) {
    NodeId c = a;
    double offLine = 0.0;
    for (NodeId n : nodes) {
      const double d = ab.normalized().cross(position(mesh, n) - xa).norm();
      if (d > offLine) {
        offLine = d;
        c = n;
      }
    }
    if (offLine > tolerance) {
      refs.push_back(c);
      r.push_back(position(mesh, c) - xa);
      out.push_back(distanceRelation(mesh, a, c, dim, scale));
      out.push_back(distanceRelation(mesh, b, c, dim, scale));
    }
  }
  const RotationOperator op = rotationOperator(a, refs, r);
  for (NodeId m : nodes) {
    if (m == a || std::find(refs.begin(), refs.end(), m) != refs.end()) {
      continue;
    }
    followRelations(mesh, a, m, op, dim, scale, out);
  }
  return out;
}

} // namespace stella
