#pragma once
// An elastic box for the linear solvers' tests, numbered and assembled as a run does it: the
// Mesh and Model of a fem::boxMesh, a MechanicalSystem (DofMap: DX, DY[, DZ] node by node, then
// one multiplier per DDL_IMPO relation), the elastic stiffness added in place by the
// VolumeAssembler into the StiffnessMatrix. The face {x_axis = 0} is then clamped by elimination
// (rows and columns zeroed, unit diagonal), or bordered by the relations' multipliers
// ([K C^T; C 0] with unit coefficients), or left free. `dense` (on request) is the same matrix
// assembled independently, densely, from the element matrices (fem::stiffness) by node.

#include "solver/assembly/tests/ElasticStudy.hpp"
#include "solver/behaviour/Elasticity.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "solver/linalg/SparseMatrix.hpp"
#include "solver/nonlinear/PointState.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace stella::testing {

enum class Clamp { Free, Eliminated, Dualised };

struct BoxClamp {
  Clamp kind = Clamp::Free;
  int axis = 0;       // the face {x_axis = 0}
  int components = 3; // DX, DY[, DZ]: the first `components` are clamped
  double young = 1000.0;
  double nu = 0.3;
  linalg::Storage storage = linalg::Storage::Upper;
  bool withDense = false; // fill ElasticBox::dense (small boxes only)
};

struct ElasticBox {
  std::shared_ptr<Mesh> mesh;
  std::shared_ptr<Model> model;
  std::unique_ptr<MechanicalSystem> system;
  linalg::SparseMatrix matrix;
  Eigen::MatrixXd dense;
  std::vector<bool> clamped; // per physical equation (elimination)

  ElasticBox(const fem::PlainMesh& p, const BoxClamp& c) : mesh(fem::toMesh(p)) {
    const bool threeD = p.dimension == 3;
    model = modelOn(mesh, threeD ? "3D" : "D_PLAN");
    const int nc = model->components;
    auto load = std::make_shared<MechanicalLoad>();
    load->model = model;
    std::vector<std::pair<NodeId, int>> face;
    for (NodeId n = 0; n < mesh->nodeCount(); ++n) {
      if (c.kind != Clamp::Free && std::abs(mesh->point(n)[static_cast<std::size_t>(c.axis)]) < 1e-12) {
        for (int comp = 0; comp < std::min(c.components, nc); ++comp) {
          face.emplace_back(n, comp);
          if (c.kind == Clamp::Dualised) {
            load->relations.push_back({{{n, comp, 1.0}}, 0.0, "DDL_IMPO"});
          }
        }
      }
    }
    system = std::make_unique<MechanicalSystem>(model, elasticMaterialOn(mesh, c.young, c.nu),
                                                std::vector<Excitation>{{load, nullptr, nullptr}},
                                                elasticEverywhere(*model), SourceLocation{});
    const DofMap& d = system->dofs();
    const int n = d.size();
    const int physical = d.physicalCount();
    const bool upper = c.storage == linalg::Storage::Upper;
    StiffnessMatrix& k = system->stiffness(upper);
    const Eigen::VectorXd none = Eigen::VectorXd::Zero(physical);
    const PointState zero = zeroPointState(*model, system->behaviours().maxInternalVariables());
    system->assembler().run(none, none, zero, behaviour::Option::ElasticTangent,
                            {nullptr, nullptr, nullptr, &k});
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < physical; ++i) {
      k.forEachInRow(i, [&](int j, double v) { entries.emplace_back(i, j, v); });
    }
    if (c.withDense) {
      dense = denseStiffness(p, c);
    }
    for (int r = 0; r < d.lagrangeCount(); ++r) { // C: one unit coefficient per relation
      const RelationTerm& t = d.relation(r).terms.front();
      const int l = physical + r;
      const int dof = d.dof(t.node, t.component);
      entries.emplace_back(l, dof, 1.0);
      entries.emplace_back(dof, l, 1.0);
      if (c.withDense) {
        dense(l, dof) = dense(dof, l) = 1.0;
      }
    }
    clamped.assign(static_cast<std::size_t>(physical), false);
    if (c.kind == Clamp::Eliminated) {
      for (const auto& [node, comp] : face) {
        clamped[static_cast<std::size_t>(d.dof(node, comp))] = true;
      }
      for (auto& e : entries) {
        if (clamped[static_cast<std::size_t>(e.row())] || clamped[static_cast<std::size_t>(e.col())]) {
          e = Eigen::Triplet<double>(e.row(), e.col(), e.row() == e.col() ? 1.0 : 0.0);
        }
      }
      for (int i = 0; i < physical && c.withDense; ++i) {
        if (clamped[static_cast<std::size_t>(i)]) {
          dense.row(i).setZero();
          dense.col(i).setZero();
          dense(i, i) = 1.0;
        }
      }
    }
    matrix = linalg::sparseMatrixOf(n, c.storage, entries);
  }

  const DofMap& dofs() const { return system->dofs(); }
  // The coordinate of an equation's node along the equation's component (physical equations).
  double coordinate(int equation) const {
    return mesh->point(dofs().node(equation))[static_cast<std::size_t>(dofs().component(equation))];
  }

private:
  // K assembled densely from the element matrices, by the DofMap's equations of each node.
  Eigen::MatrixXd denseStiffness(const fem::PlainMesh& p, const BoxClamp& c) const {
    const DofMap& d = dofs();
    const int nc = d.components();
    const fem::Modelling m = nc == 3 ? fem::Modelling::ThreeD : fem::Modelling::PlaneStrain;
    const Eigen::MatrixXd elastic = behaviour::elasticMatrix(m, {c.young, c.nu});
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(d.size(), d.size());
    fem::ElementKinematics kin;
    Eigen::MatrixXd ke;
    Eigen::MatrixXd x(p.nodesPerCell(), p.dimension);
    for (int e = 0; e < p.cellCount(); ++e) {
      for (int a = 0; a < p.nodesPerCell(); ++a) {
        x.row(a) = p.coordinates.row(p.cell(e)[a]);
      }
      fem::computeKinematics(p.cellType, m, x, kin);
      fem::stiffness(kin, elastic, ke);
      for (int a = 0; a < p.nodesPerCell(); ++a) {
        for (int b = 0; b < p.nodesPerCell(); ++b) {
          k.block(d.dof(p.cell(e)[a], 0), d.dof(p.cell(e)[b], 0), nc, nc) += ke.block(a * nc, b * nc, nc, nc);
        }
      }
    }
    return k;
  }
};

} // namespace stella::testing
