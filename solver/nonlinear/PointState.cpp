// PointState: Gauss-point fields sized from the model's RIGI rules.

#include "solver/nonlinear/PointState.hpp"

#include "solver/fem/ShapeTable.hpp"

#include <fmt/format.h>

namespace stella {

std::vector<int> gaussPointsPerCell(const Model& model) {
  std::vector<int> counts(model.cells.size(), 0);
  for (std::size_t c = 0; c < model.cells.size(); ++c) {
    if (model.cells[c].kind == ElementKind::Volume) {
      const auto role = model.cells[c].modelling == fem::Modelling::Axisymmetric
                            ? fem::IntegrationRole::AxisymmetricVolume
                            : fem::IntegrationRole::Volume;
      counts[c] = fem::shapeTable(model.mesh->cellType(static_cast<CellId>(c)), role).pointCount();
    }
  }
  return counts;
}

std::vector<std::string> stressComponents(const Model& model) {
  if (model.components == 3) {
    return {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"};
  }
  return {"SIXX", "SIYY", "SIZZ", "SIXY"};
}

PointState zeroPointState(const Model& model, int internalVariables) {
  const auto counts = gaussPointsPerCell(model);
  std::vector<std::string> strain =
      model.components == 3 ? std::vector<std::string>{"EPXX", "EPYY", "EPZZ", "EPXY", "EPXZ", "EPYZ"}
                            : std::vector<std::string>{"EPXX", "EPYY", "EPZZ", "EPXY"};
  std::vector<std::string> vari;
  for (int i = 1; i <= internalVariables; ++i) {
    vari.push_back(fmt::format("V{}", i));
  }
  return PointState{Field::perPoint(FieldSupport::GaussPoint, "EPSI_R", strain, counts),
                    Field::perPoint(FieldSupport::GaussPoint, "SIEF_R", stressComponents(model), counts),
                    Field::perPoint(FieldSupport::GaussPoint, "VARI_R", vari, counts)};
}

} // namespace stella
