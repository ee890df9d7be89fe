// ALGO_RESO_GEOM='NEWTON' with FROTTEMENT='COULOMB' (slave nodes, INTEGRATION='AUTO'): the friction
// rows T_j follow the geometry (the pairing of each iterate), so the friction terms get the variation
// of the tangents and of the projection point (ContinuousGeometricTangent.hpp, frictionRowJacobians,
// M_j = dT_j / dx). With v = u - u_start on the row's nodes, the slip s_j = T_j . v varies by
// (T_j + G_j) . du, G_j = M_j^T v, and the force -w p_j T_j (p the tangential pressure) has the
// tangent
//   w dp/ds (T_a (T_b + G_b)^T) + w p_j M_j,
// not symmetric: the factorisation is unsymmetric (symmetric()). The rows T_j + G_j are also the
// linearised slip of the sticking multipliers' constraints in the Schur complement (correct()) and
// of the Newton update of the sliding multipliers (updateSlidingPressures).

#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/ContinuousGeometricTangent.hpp"

#include "solver/mesh/MeshGeometry.hpp"

namespace stella::contact {

bool ContinuousContactConstraint::geometricFriction() const {
  return friction() && geometryNewton();
}

ContinuousContactConstraint::RowGeometry
ContinuousContactConstraint::rowGeometry(Eigen::Index row, const NodePosition& position,
                                         const Eigen::VectorXd& u) const {
  RowGeometry out;
  const ContactLink& link = links_[static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)])];
  if (link.masterCell < 0) {
    return out;
  }
  const Mesh& mesh = *definition_->mesh;
  const auto masters = mesh.cellNodes(link.masterCell);
  CellNodes cell;
  cell.type = mesh.cellType(link.masterCell);
  cell.count = static_cast<int>(masters.size());
  for (std::size_t j = 0; j < masters.size(); ++j) {
    cell.x[j] = position(masters[j]);
  }
  const std::array<Eigen::MatrixXd, 2> m = frictionRowJacobians(
      cell, info(cell.type).dimension, link.xi, position(link.slave), link.normal, link.tangent1);
  const auto size = static_cast<Eigen::Index>(3 * (1 + masters.size()));
  out.dofs.assign(static_cast<std::size_t>(size), -1);
  out.v = Eigen::VectorXd::Zero(size);
  for (Eigen::Index p = 0; p < size; ++p) {
    const auto node = static_cast<std::size_t>(p / 3);
    const auto c = static_cast<int>(p % 3);
    const int dof = c < dofs_.components() ? dofs_.dof(node == 0 ? link.slave : masters[node - 1], c) : -1;
    out.dofs[static_cast<std::size_t>(p)] = dof;
    if (dof >= 0) {
      out.v(p) = u(dof) - uStart_(dof);
    }
  }
  // the friction directions are combinations of the pairing's tangents (basis_)
  const Eigen::Matrix2d& b = basis_[static_cast<std::size_t>(row)];
  for (std::size_t j = 0; j < 2; ++j) {
    out.m[j] = b(static_cast<Eigen::Index>(j), 0) * m[0] + b(static_cast<Eigen::Index>(j), 1) * m[1];
  }
  return out;
}

void ContinuousContactConstraint::addGeometricFrictionTangent(
    Eigen::Index row, const Eigen::Vector2d& pressure, const Eigen::Matrix2d& c, const NodePosition& position,
    const Eigen::VectorXd& u, std::vector<Eigen::Triplet<double>>& tangent) const {
  const int d = frictionDirections(row);
  const RowGeometry geometry = rowGeometry(row, position, u);
  if (geometry.dofs.empty() || d == 0) {
    return;
  }
  const auto size = static_cast<Eigen::Index>(geometry.dofs.size());
  const double w = weight_(row);
  for (int b = 0; b < d; ++b) {
    // c(a, b) T_a G_b^T: the slip's variation through the geometry
    const Eigen::VectorXd g = geometry.m[static_cast<std::size_t>(b)].transpose() * geometry.v;
    for (int a = 0; a < d; ++a) {
      for (SparseRows::InnerIterator it(frictionRow(a), row); it; ++it) {
        for (Eigen::Index q = 0; q < size; ++q) {
          const int dof = geometry.dofs[static_cast<std::size_t>(q)];
          if (dof >= 0) {
            tangent.emplace_back(static_cast<int>(it.col()), dof, c(a, b) * it.value() * g(q));
          }
        }
      }
    }
  }
  for (int j = 0; j < d; ++j) { // w p_j M_j: the force's direction follows the geometry
    const Eigen::MatrixXd& m = geometry.m[static_cast<std::size_t>(j)];
    for (Eigen::Index p = 0; p < size; ++p) {
      const int dp = geometry.dofs[static_cast<std::size_t>(p)];
      for (Eigen::Index q = 0; q < size && dp >= 0; ++q) {
        const int dq = geometry.dofs[static_cast<std::size_t>(q)];
        if (dq >= 0) {
          tangent.emplace_back(dp, dq, w * pressure(j) * m(p, q));
        }
      }
    }
  }
}

void ContinuousContactConstraint::linearisedSlipRowsAt(const Eigen::VectorXd& u) {
  if (!geometricFriction()) {
    return;
  }
  const std::vector<double> displacement = nodalDisplacement(dofs_, definition_->mesh->nodeCount(), u);
  const NodePosition position = meshPositions(*definition_->mesh, &displacement);
  const auto m = static_cast<Eigen::Index>(rows_.link.size());
  std::array<std::vector<Eigen::Triplet<double>>, 2> t;
  for (Eigen::Index i = 0; i < m; ++i) {
    const int d = frictionDirections(i);
    if (d == 0) {
      continue;
    }
    const RowGeometry geometry = rowGeometry(i, position, u);
    for (int j = 0; j < d; ++j) {
      auto& out = t[static_cast<std::size_t>(j)];
      for (SparseRows::InnerIterator it(frictionRow(j), i); it; ++it) {
        out.emplace_back(static_cast<int>(i), static_cast<int>(it.col()), it.value());
      }
      if (geometry.dofs.empty()) {
        continue;
      }
      const Eigen::VectorXd g = geometry.m[static_cast<std::size_t>(j)].transpose() * geometry.v;
      for (std::size_t q = 0; q < geometry.dofs.size(); ++q) {
        if (geometry.dofs[q] >= 0) {
          out.emplace_back(static_cast<int>(i), geometry.dofs[q], g(static_cast<Eigen::Index>(q)));
        }
      }
    }
  }
  for (std::size_t j = 0; j < 2; ++j) {
    slipRows_[j].resize(m, frictionRows_[j].cols());
    slipRows_[j].setFromTriplets(t[j].begin(), t[j].end());
  }
}

const SparseRows& ContinuousContactConstraint::slipRow(int direction) const {
  return geometricFriction() ? slipRows_[static_cast<std::size_t>(direction)] : frictionRow(direction);
}

} // namespace stella::contact
