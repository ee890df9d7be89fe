#pragma once
// Shared by the finite-difference tests of ALGO_RESO_GEOM='NEWTON' (ContinuousGeometricTangentTest,
// ContinuousGeometricFrictionTest): master cells with a slave point, and a small contact assembly
// (a curved SEG3 master with two SEG2 slave cells in 2D, a warped QUAD4 with a TRIA3 slave cell in 3D).

#include "solver/assembly/DofMap.hpp"
#include "solver/contact/CellProjection.hpp"
#include "solver/contact/ContactDefinition.hpp"
#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/fem/Modelling.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/model/Model.hpp"

#include <Eigen/Sparse>

#include <memory>
#include <vector>

namespace stella::contact::geometric_test {

// Parametric dimension of a master cell type.
inline int parametric(CellType t) {
  return info(t).dimension;
}

inline Point3 cellNormal(const CellPoint& p, int dim) {
  const Point3 n = dim == 1 ? Point3{p.d1[1], -p.d1[0], 0.0} : cross(p.d1, p.d2);
  return (1.0 / norm(n)) * n;
}

// Moves variable v (0..2 the slave, then the master nodes) by h.
inline void perturb(CellNodes& cell, Point3& slave, int v, double h) {
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

// The case with variable v moved by +h and by -h (central differences).
inline std::array<KernelCase, 2> movedBothWays(const KernelCase& k, int v, double h) {
  std::array<KernelCase, 2> out{k, k};
  perturb(out[0].cell, out[0].slave, v, h);
  perturb(out[1].cell, out[1].slave, v, -h);
  return out;
}

inline CellNodes makeCell(CellType type, std::initializer_list<Point3> x) {
  CellNodes c;
  c.type = type;
  c.count = static_cast<int>(x.size());
  std::size_t i = 0;
  for (const Point3& p : x) {
    c.x[i++] = p;
  }
  return c;
}

inline std::vector<KernelCase> kernelCases() {
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

inline Eigen::MatrixXd dense(const std::vector<Eigen::Triplet<double>>& t, int n) {
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (const auto& e : t) {
    k(e.row(), e.col()) += e.value();
  }
  return k;
}

// -d forces / du by central differences (step 1e-7) of the constraint's forces at u (the pairing redone
// at each perturbed u with ALGO_RESO_GEOM='NEWTON'; multipliers and statuses as they are).
inline Eigen::MatrixXd forceDifferences(ContinuousContactConstraint& c, const Eigen::VectorXd& u) {
  constexpr double h = 1e-7;
  const auto n = u.size();
  Eigen::MatrixXd fd(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
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
  return fd;
}

} // namespace stella::contact::geometric_test
