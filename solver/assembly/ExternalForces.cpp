// ExternalForces: integration of the loads of AFFE_CHAR_MECA on skins and volumes.

#include "solver/assembly/ExternalForces.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/assembly/VolumeAssembler.hpp"
#include "solver/fem/CellCoordinates.hpp"
#include "solver/loads/SkinLoads.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

void scatter(const Mesh& mesh, CellId c, const DofMap& dofs, const Eigen::VectorXd& fe, Eigen::VectorXd& f) {
  const auto nodes = mesh.cellNodes(c);
  const int dim = dofs.components();
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (int k = 0; k < dim; ++k) {
      f(dofs.dof(nodes[i], k)) += fe(static_cast<Eigen::Index>(i) * dim + k);
    }
  }
}

Eigen::VectorXd vectorOf(const std::array<double, 3>& v, int dim) {
  Eigen::VectorXd out(dim);
  for (int k = 0; k < dim; ++k) {
    out(k) = v[static_cast<std::size_t>(k)];
  }
  return out;
}

} // namespace

Eigen::VectorXd loadForces(const MechanicalLoad& load, const DofMap& dofs, const MaterialField* materials) {
  const Model& model = *load.model;
  const Mesh& mesh = *model.mesh;
  const int dim = dofs.components();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.physicalCount());
  for (const auto& nf : load.nodalForces) {
    f(dofs.dof(nf.node, nf.component)) += nf.value;
  }
  for (const auto& p : load.pressures) {
    const auto x = cellCoordinates(mesh, p.cell, dim);
    const Eigen::VectorXd nodal = Eigen::VectorXd::Constant(x.rows(), p.pressure);
    scatter(mesh, p.cell, dofs,
            loads::pressureForces(mesh.cellType(p.cell), model.cell(p.cell).modelling, x, nodal), f);
  }
  for (const auto& s : load.surfaceForces) {
    const auto x = cellCoordinates(mesh, s.cell, dim);
    scatter(
        mesh, s.cell, dofs,
        loads::surfaceForces(mesh.cellType(s.cell), model.cell(s.cell).modelling, x, vectorOf(s.force, dim)),
        f);
  }
  for (const auto& v : load.volumeForces) {
    const auto x = cellCoordinates(mesh, v.cell, dim);
    scatter(
        mesh, v.cell, dofs,
        loads::volumeForces(mesh.cellType(v.cell), model.cell(v.cell).modelling, x, vectorOf(v.force, dim)),
        f);
  }
  for (const auto& g : load.gravity) {
    for (CellId c : g.cells) {
      const Material* m = materials != nullptr ? materials->material(c) : nullptr;
      if (m == nullptr || !m->elastic || !m->elastic->density) {
        throw UserError(msg::make("LOAD_7", {{"cell_name", mesh.cellName(c)}}));
      }
      const double rho = *m->elastic->density;
      const auto x = cellCoordinates(mesh, c, dim);
      scatter(mesh, c, dofs,
              loads::volumeForces(mesh.cellType(c), model.cell(c).modelling, x,
                                  rho * vectorOf(g.acceleration, dim)),
              f);
    }
  }
  return f;
}

Eigen::VectorXd externalForces(const std::vector<Excitation>& excitations, double time, const DofMap& dofs,
                               const MaterialField* materials, std::vector<Eigen::VectorXd>& cache) {
  cache.resize(excitations.size());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.physicalCount());
  for (std::size_t i = 0; i < excitations.size(); ++i) {
    const auto& e = excitations[i];
    if (!e.load || !e.load->hasForces()) {
      continue;
    }
    if (cache[i].size() == 0) {
      cache[i] = loadForces(*e.load, dofs, materials);
    }
    f += e.factor(time) * cache[i];
  }
  return f;
}

} // namespace stella
