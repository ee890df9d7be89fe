#pragma once
// Studies built in C++ for the tests, through the layers a run goes through (a Mesh from the
// plain arrays of fem::boxMesh: fem::toMesh): a Model with one modelling on a set of cells, an elastic
// MaterialField, the RELATION 'ELAS' of every cell. The MechanicalSystem on them numbers the
// unknowns with the run's DofMap and assembles with its VolumeAssembler and StiffnessMatrix.

#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/fem/BoxMesh.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/model/ModelBuilder.hpp"

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace stella::testing {

inline std::vector<CellId> allCells(const Mesh& mesh) {
  std::vector<CellId> all;
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    all.push_back(c);
  }
  return all;
}

// A model with `modelisation` (AFFE_MODELE's name: "3D", "D_PLAN", "AXIS_SI"...) on every cell.
inline std::shared_ptr<Model> modelOn(std::shared_ptr<const Mesh> mesh, const std::string& modelisation) {
  auto model = std::make_shared<Model>(mesh);
  assignModelling(*model, allCells(*mesh), modelisation, {});
  finishModel(*model, {});
  return model;
}

// One elastic material (E, nu) on every cell.
inline std::shared_ptr<MaterialField> elasticMaterialOn(std::shared_ptr<const Mesh> mesh, double e,
                                                        double nu) {
  auto m = std::make_shared<Material>();
  m->name = "STEEL";
  m->elastic = ElasticMaterial{e, nu, {}, {}};
  auto f = std::make_shared<MaterialField>();
  f->mesh = mesh;
  f->materials.push_back(m);
  f->cellMaterial.assign(static_cast<std::size_t>(mesh->cellCount()), 0);
  return f;
}

// RELATION='ELAS' on every cell of the model.
inline std::vector<std::string> elasticEverywhere(const Model& model) {
  return std::vector<std::string>(model.cells.size(), "ELAS");
}

} // namespace stella::testing
