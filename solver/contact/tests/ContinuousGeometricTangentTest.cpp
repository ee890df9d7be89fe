// ALGO_RESO_GEOM='NEWTON' of the continuous formulation checked by finite differences:
// (1) the second derivative of the node-to-surface gap (ContinuousGeometricTangent.hpp) against the
//     central differences of its first derivative (the pairing's row, recomputed from a fresh
//     orthogonal projection at each perturbed configuration), and that row against the differences
//     of the gap itself; on SEG2 and curved SEG3 masters (2D), warped QUAD4 and TRIA3 (3D);
// (2) the tangent the constraint assembles (K_c = -d forces / du, the pairing redone inside addForces)
//     against the central differences of its forces, on a curved SEG3 master with SEG2 slave cells and
//     on a warped QUAD4 master with a TRIA3 slave cell, PENALISATION and STANDARD (CONTACT_INIT='OUI');
//     the same comparison without the geometric term fails by orders of magnitude (the test can fail).

#include "solver/contact/ContinuousGeometricTangent.hpp"
#include "solver/assembly/DofMap.hpp"
#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/tests/ContactTestMeshes.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/model/Model.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

namespace stella::contact {
namespace {

// Parametric dimension of a master cell type.
int parametric(CellType t) {
  return info(t).dimension;
}

Point3 cellNormal(const CellPoint& p, int dim) {
  const Point3 n = dim == 1 ? Point3{p.d1[1], -p.d1[0], 0.0} : cross(p.d1, p.d2);
  return (1.0 / norm(n)) * n;
}

// The gap and its gradient over (x_s, x_1..x_n) from a fresh projection (the reference).
struct GapAndRow {
  double gap = 0.0;
  Eigen::VectorXd row;
  std::array<double, 2> xi{0, 0};
};

GapAndRow gapAndRow(const CellNodes& cell, const Point3& slave) {
  const int dim = parametric(cell.type);
  GapAndRow out;
  out.xi = projectPoint(cell, dim, slave);
  CellPoint p;
  evaluateCell(cell, out.xi, p);
  const Point3 n = cellNormal(p, dim);
  out.gap = dot(slave - p.x, n);
  out.row = Eigen::VectorXd::Zero(3 * (1 + cell.count));
  for (std::size_t c = 0; c < 3; ++c) {
    out.row(static_cast<Eigen::Index>(c)) = n[c];
    for (int j = 0; j < cell.count; ++j) {
      out.row(3 * (1 + j) + static_cast<Eigen::Index>(c)) = -p.shape.n[static_cast<std::size_t>(j)] * n[c];
    }
  }
  return out;
}

// Moves variable v (0..2 the slave, then the master nodes) by h.
void perturb(CellNodes& cell, Point3& slave, int v, double h) {
  const auto c = static_cast<std::size_t>(v % 3);
  if (v < 3) {
    slave[c] += h;
  } else {
    cell.x[static_cast<std::size_t>(v / 3 - 1)][c] += h;
  }
}

struct KernelCase {
  const char* name;
  CellNodes cell;
  Point3 slave;
};

CellNodes makeCell(CellType type, std::initializer_list<Point3> x) {
  CellNodes c;
  c.type = type;
  c.count = static_cast<int>(x.size());
  std::size_t i = 0;
  for (const Point3& p : x) {
    c.x[i++] = p;
  }
  return c;
}

std::vector<KernelCase> kernelCases() {
  return {
      {"SEG2", makeCell(CellType::SEG2, {{1.0, 0.1, 0.0}, {-1.0, -0.2, 0.0}}), {0.3, -0.1, 0.0}},
      // an arc: the curvature term; slave inside (penetrating) and outside
      {"SEG3_in",
       makeCell(CellType::SEG3, {{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, {0.1, 0.3, 0.0}}),
       {-0.4, 0.18, 0.0}},
      {"SEG3_out",
       makeCell(CellType::SEG3, {{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}, {0.1, 0.3, 0.0}}),
       {0.35, 0.45, 0.0}},
      {"QUAD4_warped",
       makeCell(CellType::QUAD4, {{-1.0, -1.0, 0.0}, {1.1, -0.9, 0.1}, {1.0, 1.0, 0.3}, {-0.9, 1.2, -0.2}}),
       {0.2, 0.3, 0.02}},
      {"TRIA3",
       makeCell(CellType::TRIA3, {{-1.0, -1.0, 0.0}, {1.0, -0.8, 0.3}, {0.1, 1.0, 0.1}}),
       {0.05, -0.1, 0.3}},
      {"QUAD8_curved",
       makeCell(CellType::QUAD8, {{-1.0, -1.0, 0.0},
                                  {1.0, -1.0, 0.0},
                                  {1.0, 1.0, 0.0},
                                  {-1.0, 1.0, 0.0},
                                  {0.0, -1.0, 0.2},
                                  {1.0, 0.0, 0.25},
                                  {0.0, 1.0, 0.2},
                                  {-1.0, 0.0, 0.15}}),
       {0.3, -0.2, 0.1}},
  };
}

TEST(ContinuousGeometricTangent, GapDerivativesMatchFiniteDifferences) {
  constexpr double h = 1e-6;
  for (const KernelCase& k : kernelCases()) {
    SCOPED_TRACE(k.name);
    const GapAndRow at = gapAndRow(k.cell, k.slave);
    const int dim = parametric(k.cell.type);
    // the projection falls inside the cell (the formula is the interior one)
    ASSERT_LE(std::abs(at.xi[0]), 1.0);
    const Eigen::MatrixXd hessian =
        gapHessian(k.cell, dim, at.xi, k.slave, Point3{at.row(0), at.row(1), at.row(2)});
    const auto size = static_cast<int>(at.row.size());
    ASSERT_EQ(hessian.rows(), size);
    Eigen::MatrixXd fd(size, size);
    double rowError = 0.0;
    for (int v = 0; v < size; ++v) {
      if (dim == 1 && v % 3 == 2) { // 2D: no z
        fd.col(v).setZero();
        continue;
      }
      CellNodes plusCell = k.cell;
      CellNodes minusCell = k.cell;
      Point3 plusSlave = k.slave;
      Point3 minusSlave = k.slave;
      perturb(plusCell, plusSlave, v, h);
      perturb(minusCell, minusSlave, v, -h);
      const GapAndRow plus = gapAndRow(plusCell, plusSlave);
      const GapAndRow minus = gapAndRow(minusCell, minusSlave);
      fd.col(v) = (plus.row - minus.row) / (2.0 * h);
      rowError = std::max(rowError, std::abs((plus.gap - minus.gap) / (2.0 * h) - at.row(v)));
    }
    if (dim == 1) { // the z rows of the 2D reference are zero too
      for (int v = 2; v < size; v += 3) {
        fd.row(v).setZero();
      }
    }
    EXPECT_LT(rowError, 1e-8);
    const double error = (hessian - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff();
    std::cout << fmt::format("[ gap d2g ] {}: max |d2g - FD| / max |FD| = {:.2e} (max |FD| {:.2e})\n", k.name,
                             error, fd.cwiseAbs().maxCoeff());
    EXPECT_LT(error, 1e-6);
    EXPECT_LT((hessian - hessian.transpose()).cwiseAbs().maxCoeff(), 1e-12 * hessian.cwiseAbs().maxCoeff());
  }
}

// A master cell and slave cells in one mesh (groups MAIT and ESCL), every node with DOFs.
struct Assembly {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::unique_ptr<DofMap> dofs;
  std::shared_ptr<ContactDefinition> definition;
  fem::Modelling modelling = fem::Modelling::PlaneStrain;

  Assembly(bool threeD, ContactAlgorithm algorithm, bool geometryNewton) {
    mesh = std::make_shared<Mesh>();
    mesh->setDimension(threeD ? 3 : 2);
    std::vector<CellId> master;
    std::vector<CellId> slave;
    if (!threeD) {
      // an arc (outward normal +y) and two SEG2 slave cells sunk into it
      const NodeId m0 = mesh->addNode({1.0, 0.0, 0.0});
      const NodeId m1 = mesh->addNode({-1.0, 0.0, 0.0});
      const NodeId m2 = mesh->addNode({0.1, 0.3, 0.0});
      const NodeId s0 = mesh->addNode({-0.5, 0.2, 0.0});
      const NodeId s1 = mesh->addNode({0.0, 0.27, 0.0});
      const NodeId s2 = mesh->addNode({0.45, 0.21, 0.0});
      master.push_back(mesh->addCell(CellType::SEG3, std::vector<NodeId>{m0, m1, m2}));
      slave.push_back(mesh->addCell(CellType::SEG2, std::vector<NodeId>{s1, s0}));
      slave.push_back(mesh->addCell(CellType::SEG2, std::vector<NodeId>{s2, s1}));
    } else {
      // a warped QUAD4 (outward normal about +z) and a TRIA3 slave cell 0.05 below it
      const std::array<Point3, 4> corners{Point3{-1.0, -1.0, 0.0}, Point3{1.1, -0.9, 0.1},
                                          Point3{1.0, 1.0, 0.3}, Point3{-0.9, 1.2, -0.2}};
      std::vector<NodeId> quad;
      for (const Point3& p : corners) {
        quad.push_back(mesh->addNode(p));
      }
      master.push_back(mesh->addCell(CellType::QUAD4, quad));
      std::vector<NodeId> tria;
      for (const auto& [x, y] :
           std::array<std::pair<double, double>, 3>{{{-0.3, -0.2}, {0.4, -0.1}, {0.0, 0.5}}}) {
        const double z = 0.25 * ((1 - x) * (1 - y) * 0.0 + (1 + x) * (1 - y) * 0.1 + (1 + x) * (1 + y) * 0.3 +
                                 (1 - x) * (1 + y) * -0.2);
        tria.push_back(mesh->addNode({x, y, z - 0.05}));
      }
      slave.push_back(mesh->addCell(CellType::TRIA3, tria));
      modelling = fem::Modelling::ThreeD;
    }
    mesh->setCellGroup("MAIT", master);
    mesh->setCellGroup("ESCL", slave);
    model = std::make_shared<Model>(mesh);
    model->components = threeD ? 3 : 2;
    model->activeNodes.assign(static_cast<std::size_t>(mesh->nodeCount()), true);
    dofs = std::make_unique<DofMap>(*model);
    definition = std::make_shared<ContactDefinition>();
    definition->mesh = mesh;
    definition->settings.formulation = Formulation::Continue;
    definition->settings.continuous.geometryNewton = geometryNewton;
    ContactZone zone;
    zone.masterGroup = "MAIT";
    zone.slaveGroup = "ESCL";
    zone.algorithm = algorithm;
    zone.continuous.penalty = 1.0e3;
    zone.continuous.augmentation = 1.0e3;
    zone.continuous.init = ContactInit::Yes;
    definition->zones.push_back(zone);
  }
};

Eigen::MatrixXd dense(const std::vector<Eigen::Triplet<double>>& t, int n) {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (const auto& e : t) {
    k(e.row(), e.col()) += e.value();
  }
  return k;
}

class AssembledGeometricTangent : public ::testing::TestWithParam<std::tuple<bool, ContactAlgorithm>> {};

TEST_P(AssembledGeometricTangent, MatchesFiniteDifferencesOfTheForces) {
  const auto [threeD, algorithm] = GetParam();
  Assembly newton(threeD, algorithm, true);
  Assembly fixed(threeD, algorithm, false);
  const int n = newton.dofs->physicalCount();
  // a general configuration: every node moved a little
  Eigen::VectorXd u(n);
  for (int i = 0; i < n; ++i) {
    u(i) = 0.01 * std::sin(1.7 * i + 0.3);
  }
  auto tangentOf = [&](Assembly& a) {
    ContinuousContactConstraint c(a.definition, *a.dofs, a.modelling);
    c.initialize();
    c.beginStep(u, 1.0);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    std::vector<Eigen::Triplet<double>> t;
    c.addForces(u, f, &t);
    return dense(t, n);
  };
  const Eigen::MatrixXd k = tangentOf(newton);
  const Eigen::MatrixXd kFixed = tangentOf(fixed);
  ContinuousContactConstraint c(newton.definition, *newton.dofs, newton.modelling);
  c.initialize();
  c.beginStep(u, 1.0);
  constexpr double h = 1e-7;
  Eigen::MatrixXd fd(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd fp = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd fm = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd up = u;
    Eigen::VectorXd um = u;
    up(j) += h;
    um(j) -= h;
    c.addForces(up, fp, nullptr);
    c.addForces(um, fm, nullptr);
    fd.col(j) = -(fp - fm) / (2.0 * h);
  }
  const double scale = fd.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  const double error = (k - fd).cwiseAbs().maxCoeff() / scale;
  const double errorWithout = (kFixed - fd).cwiseAbs().maxCoeff() / scale;
  std::cout << fmt::format(
      "[ assembled ] {} {}: max |K - FD| / max |FD| = {:.2e} (without the geometric term "
      "{:.2e})\n",
      threeD ? "3D QUAD4/TRIA3" : "2D SEG3/SEG2",
      algorithm == ContactAlgorithm::ContinuePenalty ? "PENALISATION" : "STANDARD", error, errorWithout);
  EXPECT_LT(error, 1e-5);
  EXPECT_GT(errorWithout, 1e-3);
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale); // frictionless: symmetric
}

INSTANTIATE_TEST_SUITE_P(MastersAndAlgorithms, AssembledGeometricTangent,
                         ::testing::Combine(::testing::Bool(),
                                            ::testing::Values(ContactAlgorithm::ContinuePenalty,
                                                              ContactAlgorithm::Standard)));

} // namespace
} // namespace stella::contact
