#pragma once
// Test helpers for the assembly: a Mesh from a structured box (fem::boxMesh) and one isotropic
// elastic material on every cell.

#include "solver/fem/BoxMesh.hpp"
#include "solver/mesh/Mesh.hpp"
#include "solver/model/MaterialField.hpp"

#include <memory>

namespace stella::testing {

inline std::shared_ptr<Mesh> meshOfBox(const fem::PlainMesh& p) {
  auto mesh = std::make_shared<Mesh>();
  mesh->setDimension(p.dimension);
  for (int i = 0; i < p.nodeCount(); ++i) {
    Point3 x{0, 0, 0};
    for (int d = 0; d < p.dimension; ++d) {
      x[static_cast<std::size_t>(d)] = p.coordinates(i, d);
    }
    mesh->addNode(x);
  }
  for (int c = 0; c < p.cellCount(); ++c) {
    mesh->addCell(p.cellType, std::span<const NodeId>(p.cell(c), static_cast<std::size_t>(p.nodesPerCell())));
  }
  return mesh;
}

inline std::shared_ptr<MaterialField> elasticOn(std::shared_ptr<const Mesh> mesh, double e, double nu) {
  auto material = std::make_shared<Material>();
  material->name = "MAT";
  material->elastic = ElasticMaterial{e, nu, {}, {}};
  auto field = std::make_shared<MaterialField>();
  field->mesh = std::move(mesh);
  field->materials.push_back(material);
  field->cellMaterial.assign(static_cast<std::size_t>(field->mesh->cellCount()), 0);
  return field;
}

} // namespace stella::testing
