// VolumeAssembler: element integration and scattering over the volume cells.

#include "solver/assembly/VolumeAssembler.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/fem/CellCoordinates.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "solver/fem/GreenLagrange.hpp"
#include "solver/fem/Kinematics.hpp"

#include <fmt/format.h>

namespace stella {

VolumeAssembler::VolumeAssembler(const Model& model, const DofMap& dofs, const CellBehaviours& behaviours,
                                 const ElementCharacteristics* springs)
    : model_(model), dofs_(dofs), behaviours_(behaviours), cells_(model.cellsOfKind(ElementKind::Volume)),
      springs_(springs) {}

void VolumeAssembler::addSprings(const Eigen::VectorXd& uStart, const Eigen::VectorXd& du,
                                 AssemblyOutput out) const {
  if (springs_ == nullptr) {
    return;
  }
  for (const DiscreteSpring& s : springs_->springs) {
    for (int c = 0; c < dofs_.components(); ++c) {
      const double k = s.stiffness[static_cast<std::size_t>(c)];
      const int eq = dofs_.dof(s.node, c);
      if (out.matrix != nullptr) {
        out.matrix->emplace_back(eq, eq, k);
      }
      if (out.stiffness != nullptr) {
        out.stiffness->add(eq, eq, k);
      }
      if (out.internalForces != nullptr) {
        (*out.internalForces)(eq) += k * (uStart(eq) + du(eq));
      }
    }
  }
}

void VolumeAssembler::cellDofs(CellId c, std::vector<int>& dofs) const {
  dofs.clear();
  for (NodeId n : model_.mesh->cellNodes(c)) {
    for (int k = 0; k < dofs_.components(); ++k) {
      dofs.push_back(dofs_.dof(n, k));
    }
  }
}

namespace {

Eigen::VectorXd gather(const Eigen::VectorXd& u, const std::vector<int>& dofs) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    out(static_cast<Eigen::Index>(i)) = u(dofs[i]);
  }
  return out;
}

Eigen::Map<const Eigen::VectorXd> row(const Field& f, std::size_t point) {
  const auto s = f.entity(point);
  return Eigen::Map<const Eigen::VectorXd>(s.data(), static_cast<Eigen::Index>(s.size()));
}

Diagnostic degenerateCellDiagnostic(const Mesh& mesh, CellId c, const fem::DegenerateElementError& e,
                                    fem::Modelling m) {
  const bool plane = dimension(mesh.cellType(c)) == 2;
  return msg::make(plane ? "ELEM_1.2" : "ELEM_1", {{"cell", mesh.cellName(c)},
                                                   {"type", name(mesh.cellType(c))},
                                                   {"jacobian", e.jacobian()},
                                                   {"point", e.gaussPoint() + 1}})
      .withNote(m == fem::Modelling::Axisymmetric ? msg::text("ELEM_1.n1") : msg::text("ELEM_1.n2"));
}

// GROT_GDEP at the points of one cell: element displacements at the start and end of the step,
// and the reference gradients of each point (for the geometric stiffness).
struct LargeDisplacementCell {
  Eigen::VectorXd uStart;
  Eigen::VectorXd uEnd;
  std::vector<Eigen::MatrixXd> gradients;
};

// The strain increment at point q: B du (PETIT), or E(uEnd) - E(uStart) (GROT_GDEP, `large` not
// null), in which case kin.b[q] becomes B_F at the end of the step (or at its start when the option
// does not integrate: the prediction's tangent), so that the element integrals below use it.
Eigen::VectorXd strainIncrement(fem::ElementKinematics& kin, int q, const Eigen::VectorXd& due,
                                LargeDisplacementCell* large, behaviour::Option option) {
  if (large == nullptr) {
    return fem::strainAt(kin, q, due);
  }
  const Eigen::MatrixXd g = fem::referenceGradients(kin, q);
  const Eigen::Matrix3d f0 = fem::deformationGradient(kin, g, large->uStart);
  const Eigen::Matrix3d f1 = fem::deformationGradient(kin, g, large->uEnd);
  kin.b[static_cast<std::size_t>(q)] =
      fem::greenLagrangeVariation(kin, g, behaviour::integrates(option) ? f1 : f0);
  large->gradients[static_cast<std::size_t>(q)] = g;
  return fem::greenLagrangeStrain(kin.modelling, f1) - fem::greenLagrangeStrain(kin.modelling, f0);
}

} // namespace

AssemblyStatus VolumeAssembler::run(const Eigen::VectorXd& uStart, const Eigen::VectorXd& du,
                                    const PointState& start, behaviour::Option option,
                                    AssemblyOutput out) const {
  const Mesh& mesh = *model_.mesh;
  const int dim = dofs_.components();
  AssemblyStatus status;
  fem::ElementKinematics kin;
  std::vector<int> dofs;
  std::vector<Eigen::VectorXd> stresses;
  std::vector<Eigen::MatrixXd> tangents;
  Eigen::MatrixXd ke;
  Eigen::VectorXd fe;
  LargeDisplacementCell large;
  const bool wantMatrix = out.matrix != nullptr || out.stiffness != nullptr;
  for (std::size_t index = 0; index < cells_.size(); ++index) {
    const CellId c = cells_[index];
    const fem::Modelling m = model_.cell(c).modelling;
    const int ns = fem::strainSize(m);
    try {
      fem::computeKinematics(mesh.cellType(c), m, cellCoordinates(mesh, c, dim), kin,
                             model_.cell(c).volumeStrain);
    } catch (const fem::DegenerateElementError& e) {
      throw UserError(degenerateCellDiagnostic(mesh, c, e, m));
    }
    cellDofs(c, dofs);
    const Eigen::VectorXd due = gather(du, dofs);
    // GROT_GDEP; the elastic matrix (MATRICE='ELASTIQUE') is the small-strain one of the reference
    const bool largeCell = behaviours_.strainMeasure(c) == fem::StrainMeasure::GreenLagrange &&
                           option != behaviour::Option::ElasticTangent;
    if (largeCell) {
      large.uStart = gather(uStart, dofs);
      large.uEnd = large.uStart + due;
      large.gradients.resize(static_cast<std::size_t>(kin.pointCount()));
    }
    const behaviour::Behaviour& b = *behaviours_.of(c);
    const auto nv = static_cast<std::size_t>(b.internalVariableCount());
    stresses.resize(static_cast<std::size_t>(kin.pointCount()));
    tangents.resize(static_cast<std::size_t>(kin.pointCount()));
    const std::size_t first = start.stress.firstPoint(static_cast<std::size_t>(c));
    for (int q = 0; q < kin.pointCount(); ++q) {
      const std::size_t p = first + static_cast<std::size_t>(q);
      Eigen::VectorXd deps = strainIncrement(kin, q, due, largeCell ? &large : nullptr, option);
      Eigen::VectorXd sigma(ns);
      std::vector<double> vari(nv, 0.0);
      auto& t = tangents[static_cast<std::size_t>(q)];
      const auto varStart = start.internal.entity(p).subspan(0, nv);
      auto s = behaviour::integrateInModelling(b, m, option, row(start.strain, p), deps, row(start.stress, p),
                                               varStart, sigma, vari, wantMatrix ? &t : nullptr);
      if (s == behaviour::IntegrationStatus::Failed && !status.failedCell) {
        status.failedCell = c;
      }
      if (!behaviour::integrates(option)) {
        sigma = row(start.stress, p);
        std::copy(varStart.begin(), varStart.end(), vari.begin());
        deps.setZero();
      }
      stresses[static_cast<std::size_t>(q)] = sigma;
      if (out.end != nullptr) {
        auto eps = out.end->strain.entity(p);
        auto sig = out.end->stress.entity(p);
        auto var = out.end->internal.entity(p);
        for (int k = 0; k < ns; ++k) {
          eps[static_cast<std::size_t>(k)] = row(start.strain, p)(k) + deps(k);
          sig[static_cast<std::size_t>(k)] = sigma(k);
        }
        std::copy(vari.begin(), vari.end(), var.begin());
      }
    }
    if (out.internalForces != nullptr) {
      fem::internalForces(kin, stresses, fe);
      for (std::size_t i = 0; i < dofs.size(); ++i) {
        (*out.internalForces)(dofs[i]) += fe(static_cast<Eigen::Index>(i));
      }
    }
    if (wantMatrix) {
      fem::stiffness(kin, tangents, ke);
      for (int q = 0; largeCell && q < kin.pointCount(); ++q) {
        const auto uq = static_cast<std::size_t>(q);
        fem::addGeometricStiffness(kin, large.gradients[uq], stresses[uq], kin.weights[uq], ke);
      }
    }
    if (out.stiffness != nullptr) {
      out.stiffness->addCell(index, ke);
    }
    if (out.matrix != nullptr) {
      for (std::size_t i = 0; i < dofs.size(); ++i) {
        for (std::size_t j = 0; j < dofs.size(); ++j) {
          out.matrix->emplace_back(dofs[i], dofs[j],
                                   ke(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
        }
      }
    }
  }
  addSprings(uStart, du, out);
  return status;
}

} // namespace stella
