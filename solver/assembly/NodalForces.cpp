// NodalForces: B^T sigma assembled from a stored SIEF_ELGA.

#include "solver/assembly/NodalForces.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/assembly/VolumeAssembler.hpp"
#include "solver/fem/CellCoordinates.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "solver/fem/Kinematics.hpp"

namespace stella {

namespace {

// The displacements of a cell's nodes (node by node) read from a DEPL field.
Eigen::VectorXd cellDisplacement(const Model& model, CellId c, int dim, const Field& depl) {
  const auto nodes = model.mesh->cellNodes(c);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(nodes.size()) * dim);
  for (int k = 0; k < dim; ++k) {
    const auto cmp = depl.componentIndex(Model::componentName(k));
    STELLA_ASSERT(cmp.has_value(), "DEPL without a displacement component");
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      u(static_cast<Eigen::Index>(i) * dim + k) = depl.value(static_cast<std::size_t>(nodes[i]), *cmp);
    }
  }
  return u;
}

} // namespace

Eigen::VectorXd forcesFromStress(const Model& model, const DofMap& dofs, const Field& stress,
                                 const std::vector<fem::StrainMeasure>* strains, const Field* depl) {
  const Mesh& mesh = *model.mesh;
  const int dim = dofs.components();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.physicalCount());
  fem::ElementKinematics kin;
  std::vector<Eigen::VectorXd> sigmas;
  Eigen::VectorXd fe;
  for (CellId c : model.cellsOfKind(ElementKind::Volume)) {
    fem::computeKinematics(mesh.cellType(c), model.cell(c).modelling, cellCoordinates(mesh, c, dim), kin,
                           model.cell(c).volumeStrain);
    const std::size_t first = stress.firstPoint(static_cast<std::size_t>(c));
    sigmas.resize(static_cast<std::size_t>(kin.pointCount()));
    for (int q = 0; q < kin.pointCount(); ++q) {
      const auto s = stress.entity(first + static_cast<std::size_t>(q));
      sigmas[static_cast<std::size_t>(q)] =
          Eigen::Map<const Eigen::VectorXd>(s.data(), static_cast<Eigen::Index>(s.size()));
    }
    if (strains != nullptr && (*strains)[static_cast<std::size_t>(c)] == fem::StrainMeasure::GreenLagrange) {
      STELLA_ASSERT(depl != nullptr, "GROT_GDEP forces without DEPL");
      const Eigen::VectorXd u = cellDisplacement(model, c, dim, *depl);
      for (int q = 0; q < kin.pointCount(); ++q) { // B_F^T S
        const Eigen::MatrixXd g = fem::referenceGradients(kin, q);
        kin.b[static_cast<std::size_t>(q)] =
            fem::greenLagrangeVariation(kin, g, fem::deformationGradient(kin, g, u));
      }
    }
    fem::internalForces(kin, sigmas, fe);
    const auto nodes = mesh.cellNodes(c);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      for (int k = 0; k < dim; ++k) {
        f(dofs.dof(nodes[i], k)) += fe(static_cast<Eigen::Index>(i) * dim + k);
      }
    }
  }
  return f;
}

} // namespace stella
