// AFFE_MODELE's assignment of element kinds to cells, with the checks code_aster makes.

#include "solver/model/ModelBuilder.hpp"

#include "interpreter/Diagnostics.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

void setComponents(Model& model, int components, const std::string& name, const SourceLocation& at) {
  const bool first =
      model.cellsOfKind(ElementKind::Volume).empty() && model.cellsOfKind(ElementKind::Discrete).empty();
  if (!first && model.components != components) {
    throw UserError(
        Diagnostic::fatal("MODEL_3",
                          fmt::format("MODELISATION='{}' has {} displacement components, the model "
                                      "already has {}",
                                      name, components, model.components),
                          at)
            .withNote("a model is either 2D (D_PLAN, C_PLAN, AXIS, 2D_DIS_T) or 3D (3D, DIS_T)"));
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
      throw UserError(
          Diagnostic::fatal("MODEL_2", fmt::format("no POI1 cell in the selection can carry '{}'", name), at)
              .withNote("discrete springs go on point cells (POI1): create them with CREA_MAILLAGE "
                        "CREA_POI1 or in the mesher"));
    }
    return;
  }
  const auto variant = fem::modellingVariantFromName(name);
  if (!variant) {
    throw UserError(
        Diagnostic::fatal("MODEL_1", fmt::format("MODELISATION='{}' is not implemented yet", name), at)
            .withNote("available: 3D, D_PLAN, C_PLAN, AXIS, their mean-dilatation variants 3D_SI, "
                      "D_PLAN_SI, AXIS_SI, and DIS_T, 2D_DIS_T"));
  }
  const auto m = std::optional<fem::Modelling>(variant->modelling);
  setComponents(model, fem::spaceDimension(*m), name, at);
  if (model.hasVolume && model.modelling != *m) {
    throw UserError(Diagnostic::fatal("MODEL_3",
                                      fmt::format("MODELISATION='{}' on a model that already has '{}' cells",
                                                  name, fem::modellingName(model.modelling)),
                                      at)
                        .withNote("one model carries one volume modelisation"));
  }
  if (assignContinuum(model, cells, *variant) == 0 && !model.hasVolume) {
    throw UserError(
        Diagnostic::fatal("MODEL_2",
                          fmt::format("no cell of the selection has dimension {}, so none can carry "
                                      "MODELISATION='{}'",
                                      fem::spaceDimension(*m), name),
                          at)
            .withNote(fem::spaceDimension(*m) == 2 ? "2D modelisations need surface cells (TRIA, QUAD)"
                                                   : "'3D' needs volume cells (TETRA, PENTA, PYRAM, HEXA)"));
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
    throw UserError(Diagnostic::fatal("MODEL_6", "the model has no element", at));
  }
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    if (!model.nodeActive(n)) {
      continue;
    }
    const Point3 x = mesh.point(n);
    if (model.components == 2 && std::fabs(x[2]) > 0.0) {
      throw UserError(
          Diagnostic::fatal("MODEL_4",
                            fmt::format("node {} has z = {}, a 2D model needs every node in the plane z = 0",
                                        mesh.nodeName(n), x[2]),
                            at)
              .withNote("mesh the section in the (x, y) plane"));
    }
    if (model.hasVolume && model.modelling == fem::Modelling::Axisymmetric && x[0] < 0.0) {
      throw UserError(
          Diagnostic::fatal(
              "MODEL_5", fmt::format("node {} has r = x = {} < 0 in an AXIS model", mesh.nodeName(n), x[0]),
              at)
              .withNote("in AXIS, x is the radius: the section lies in x >= 0, the axis is x = 0"));
    }
  }
}

} // namespace stella
