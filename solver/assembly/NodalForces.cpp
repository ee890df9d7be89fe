// NodalForces: B^T sigma assembled from a stored SIEF_ELGA.

#include "solver/assembly/NodalForces.hpp"

#include "solver/assembly/VolumeAssembler.hpp"
#include "solver/fem/ElementMatrices.hpp"
#include "solver/fem/Kinematics.hpp"

namespace stella {

Eigen::VectorXd forcesFromStress(const Model& model, const DofMap& dofs, const Field& stress) {
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
