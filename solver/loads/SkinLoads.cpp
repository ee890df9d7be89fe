// Integration of pressure, surface and volume forces on cells.

#include "solver/loads/SkinLoads.hpp"

#include "solver/fem/Kinematics.hpp"
#include "solver/fem/ShapeTable.hpp"

#include <stdexcept>
#include <string>

namespace stella::loads {

std::vector<SkinPoint> skinPoints(CellType type, fem::Modelling m,
                                  const Eigen::Ref<const Eigen::MatrixXd>& x) {
  const int dim = fem::spaceDimension(m);
  if (stella::dimension(type) != dim - 1) {
    throw std::invalid_argument(std::string("cell type ") + std::string(name(type)) +
                                " is not a skin of modelling " + std::string(fem::modellingName(m)));
  }
  const fem::ShapeTable& t = fem::shapeTable(type, fem::IntegrationRole::Skin);
  std::vector<SkinPoint> out(static_cast<std::size_t>(t.pointCount()));
  for (int q = 0; q < t.pointCount(); ++q) {
    const auto uq = static_cast<std::size_t>(q);
    SkinPoint& s = out[uq];
    s.values = t.values[uq];
    s.point.setZero();
    s.point.head(dim) = x.transpose() * s.values;
    const Eigen::MatrixXd tangents = x.transpose() * t.gradients[uq]; // dim x (dim-1)
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    if (dim == 2) {
      n = Eigen::Vector3d(tangents(1, 0), -tangents(0, 0), 0.0);
    } else {
      n = Eigen::Vector3d(tangents.col(0)).cross(Eigen::Vector3d(tangents.col(1)));
    }
    const double ds = n.norm();
    s.normal = n / ds;
    s.weight = t.rule->weights[uq] * ds * (m == fem::Modelling::Axisymmetric ? s.point[0] : 1.0);
  }
  return out;
}

Eigen::VectorXd pressureForces(CellType type, fem::Modelling m, const Eigen::Ref<const Eigen::MatrixXd>& x,
                               const Eigen::Ref<const Eigen::VectorXd>& nodalPressure) {
  const int dim = fem::spaceDimension(m);
  const int nno = static_cast<int>(x.rows());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(nno * dim);
  for (const SkinPoint& s : skinPoints(type, m, x)) {
    const double p = s.values.dot(nodalPressure);
    for (int i = 0; i < nno; ++i) {
      f.segment(i * dim, dim) -= s.weight * p * s.values[i] * s.normal.head(dim);
    }
  }
  return f;
}

Eigen::VectorXd surfaceForces(CellType type, fem::Modelling m, const Eigen::Ref<const Eigen::MatrixXd>& x,
                              const Eigen::Ref<const Eigen::VectorXd>& force) {
  const int dim = fem::spaceDimension(m);
  const int nno = static_cast<int>(x.rows());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(nno * dim);
  for (const SkinPoint& s : skinPoints(type, m, x)) {
    for (int i = 0; i < nno; ++i) {
      f.segment(i * dim, dim) += s.weight * s.values[i] * force;
    }
  }
  return f;
}

Eigen::VectorXd volumeForces(CellType type, fem::Modelling m, const Eigen::Ref<const Eigen::MatrixXd>& x,
                             const Eigen::Ref<const Eigen::VectorXd>& force) {
  fem::ElementKinematics k;
  fem::computeKinematics(type, m, x, k);
  const int dim = fem::spaceDimension(m);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(k.dofCount);
  for (int q = 0; q < k.pointCount(); ++q) {
    const auto uq = static_cast<std::size_t>(q);
    const Eigen::VectorXd& n = k.table->values[uq];
    for (int i = 0; i < k.nodeCount; ++i) {
      f.segment(i * dim, dim) += k.weights[uq] * n[i] * force;
    }
  }
  return f;
}

} // namespace stella::loads
