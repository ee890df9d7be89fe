// Strain-displacement matrices for 3D, plane strain/stress and axisymmetric elements.

#include "solver/fem/Kinematics.hpp"

#include <string>

namespace stella::fem {
namespace {

// B-bar: B_q += (1/3) m (bbar - tr B_q), m = (1, 1, 1, 0...) on the normal strains, where tr B_q
// is the volumetric-strain row at point q and bbar its weighted mean over the cell. A strain
// field with constant trace is left unchanged (patch tests hold).
void replaceVolumetricByCellMean(ElementKinematics& k) {
  const Eigen::Index n = k.dofCount;
  Eigen::RowVectorXd mean = Eigen::RowVectorXd::Zero(n);
  double volume = 0.0;
  for (int q = 0; q < k.pointCount(); ++q) {
    const auto uq = static_cast<std::size_t>(q);
    mean += k.weights[uq] * k.b[uq].topRows(3).colwise().sum();
    volume += k.weights[uq];
  }
  mean /= volume;
  for (int q = 0; q < k.pointCount(); ++q) {
    Eigen::MatrixXd& b = k.b[static_cast<std::size_t>(q)];
    const Eigen::RowVectorXd correction = (mean - b.topRows(3).colwise().sum()) / 3.0;
    for (int i = 0; i < 3; ++i) {
      b.row(i) += correction;
    }
  }
}

} // namespace

void computeKinematics(CellType type, Modelling m, const Eigen::Ref<const Eigen::MatrixXd>& x,
                       ElementKinematics& out, VolumeStrain volumeStrain) {
  const int dim = spaceDimension(m);
  if (stella::dimension(type) != dim) {
    throw std::invalid_argument(std::string("cell type ") + std::string(name(type)) +
                                " cannot be a volume element of modelling " + std::string(modellingName(m)));
  }
  const ShapeTable& t = shapeTable(type, m == Modelling::Axisymmetric ? IntegrationRole::AxisymmetricVolume
                                                                      : IntegrationRole::Volume);
  const int nno = t.nodeCount;
  const int npg = t.pointCount();
  const int ns = strainSize(m);
  out.modelling = m;
  out.volumeStrain = volumeStrain;
  out.table = &t;
  out.nodeCount = nno;
  out.dofCount = nno * dim;
  out.weights.resize(static_cast<std::size_t>(npg));
  out.points.resize(static_cast<std::size_t>(npg));
  out.b.resize(static_cast<std::size_t>(npg));
  // A 2D cell may be numbered clockwise (as Salome and older meshers write them): like code_aster,
  // the weights use |det J| and the gradients through J^-1 are right whatever the sign. The sign
  // must not change inside the cell (a distorted cell); a 3D cell must have det J > 0.
  double orientation = 1.0;
  for (int q = 0; q < npg; ++q) {
    const auto uq = static_cast<std::size_t>(q);
    const Eigen::MatrixXd& dn = t.gradients[uq];
    const Eigen::VectorXd& n = t.values[uq];
    // fixed maximum sizes: no heap allocation per Gauss point
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3> jac =
        x.transpose() * dn; // dx_i / dxi_j
    const double det = jac.determinant();
    if (dim == 2 && q == 0 && det < 0.0) {
      orientation = -1.0;
    }
    if (!(orientation * det > 0.0)) {
      throw DegenerateElementError(q, det);
    }
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3> inv = jac.inverse();
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 27, 3> g = dn * inv; // dN / dx
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p.head(dim) = x.transpose() * n;
    out.points[uq] = p;
    double w = t.rule->weights[uq] * orientation * det;
    Eigen::MatrixXd& b = out.b[uq];
    b.setZero(ns, nno * dim);
    if (dim == 3) {
      for (int i = 0; i < nno; ++i) {
        const double gx = g(i, 0), gy = g(i, 1), gz = g(i, 2);
        const int c = 3 * i;
        b(0, c) = gx;
        b(1, c + 1) = gy;
        b(2, c + 2) = gz;
        b(3, c) = gy;
        b(3, c + 1) = gx;
        b(4, c) = gz;
        b(4, c + 2) = gx;
        b(5, c + 1) = gz;
        b(5, c + 2) = gy;
      }
    } else {
      const double r = p[0];
      if (m == Modelling::Axisymmetric) {
        if (!(r > 0.0)) {
          throw DegenerateElementError(q, r);
        }
        w *= r;
      }
      for (int i = 0; i < nno; ++i) {
        const double gx = g(i, 0), gy = g(i, 1);
        const int c = 2 * i;
        b(0, c) = gx;
        b(1, c + 1) = gy;
        if (m == Modelling::Axisymmetric) {
          b(2, c) = n[i] / r;
        }
        b(3, c) = gy;
        b(3, c + 1) = gx;
      }
    }
    out.weights[uq] = w;
  }
  if (volumeStrain == VolumeStrain::CellMean) {
    replaceVolumetricByCellMean(out);
  }
}

} // namespace stella::fem
