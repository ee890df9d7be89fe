// AFFE_MODELE's assignment of element kinds to cells, with the checks code_aster makes.

#include "solver/model/ModelBuilder.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

void setComponents(Model& model, int components, const std::string& name, const SourceLocation& at) {
  const bool first =
      model.cellsOfKind(ElementKind::Volume).empty() && model.cellsOfKind(ElementKind::Discrete).empty();
  if (!first && model.components != components) {
    throw UserError(msg::make(
        "MODEL_3", {{"name", name}, {"components", components}, {"components_2", model.components}}, at));
  }
  model.components = components;
}

int assignDiscrete(Model& model, std::span<const CellId> cells) {
  int count = 0;
  for (CellId c : cells) {
    if (model.mesh->cellType(c) == CellType::POI1) {
      model.cells[static_cast<std::size_t>(c)] = {ElementKind::Discrete, model.modelling};
      ++count;
    }
  }
  return count;
}

int assignContinuum(Model& model, std::span<const CellId> cells, fem::ModellingVariant variant) {
  const fem::Modelling m = variant.modelling;
  const int dim = fem::spaceDimension(m);
  int volumes = 0;
  for (CellId c : cells) {
    const int d = dimension(model.mesh->cellType(c));
    auto& cell = model.cells[static_cast<std::size_t>(c)];
    if (d == dim) {
      cell = {ElementKind::Volume, m, variant.volumeStrain};
      ++volumes;
    } else if (d == dim - 1 && cell.kind != ElementKind::Volume) {
      cell = {ElementKind::Skin, m};
    }
  }
  return volumes;
}

} // namespace

void assignModelling(Model& model, std::span<const CellId> cells, const std::string& name,
                     const SourceLocation& at) {
  if (name == "DIS_T" || name == "2D_DIS_T") {
    setComponents(model, name == "DIS_T" ? 3 : 2, name, at);
    if (assignDiscrete(model, cells) == 0) {
      throw UserError(msg::make("MODEL_2", {{"name", name}}, at));
    }
    return;
  }
  const auto variant = fem::modellingVariantFromName(name);
  if (!variant) {
    throw UserError(msg::make("MODEL_1", {{"name", name}}, at));
  }
  const auto m = std::optional<fem::Modelling>(variant->modelling);
  setComponents(model, fem::spaceDimension(*m), name, at);
  if (model.hasVolume && model.modelling != *m) {
    throw UserError(msg::make("MODEL_3.2",
                              {{"name", name}, {"modelling_name", fem::modellingName(model.modelling)}}, at));
  }
  if (assignContinuum(model, cells, *variant) == 0 && !model.hasVolume) {
    throw UserError(
        msg::make("MODEL_2.2", {{"space_dimension", fem::spaceDimension(*m)}, {"name", name}}, at)
            .withNote(fem::spaceDimension(*m) == 2 ? msg::text("MODEL_2.n1") : msg::text("MODEL_2.n2")));
  }
  model.modelling = *m;
  model.hasVolume = true;
}

void finishModel(Model& model, const SourceLocation& at) {
  const Mesh& mesh = *model.mesh;
  model.activeNodes.assign(static_cast<std::size_t>(mesh.nodeCount()), false);
  bool any = false;
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    if (model.cell(c).kind == ElementKind::None) {
      continue;
    }
    any = true;
    for (NodeId n : mesh.cellNodes(c)) {
      model.activeNodes[static_cast<std::size_t>(n)] = true;
    }
  }
  if (!any) {
    throw UserError(msg::make("MODEL_6", {}, at));
  }
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    if (!model.nodeActive(n)) {
      continue;
    }
    const Point3 x = mesh.point(n);
    if (model.components == 2 && std::fabs(x[2]) > 0.0) {
      throw UserError(msg::make("MODEL_4", {{"node_name", mesh.nodeName(n)}, {"x", x[2]}}, at));
    }
    if (model.hasVolume && model.modelling == fem::Modelling::Axisymmetric && x[0] < 0.0) {
      throw UserError(msg::make("MODEL_5", {{"node_name", mesh.nodeName(n)}, {"x", x[0]}}, at));
    }
  }
}

} // namespace stella
