// CALC_PRESSION: adds PRES_NOEU (component PRES) to the steps of a result (TOUT_ORDRE, or INST
// with CRITERE/PRECISION): the normal pressure p = -n.sigma.n on the skin cells of GROUP_MA
// (solver/post/SkinPressure.hpp), sigma the nodal stress (SIEF_ELGA extrapolated to the cell
// nodes and averaged at the nodes over the volume cells, as SIEF_NOEU), n on the initial
// geometry (GEOMETRIE='INITIALE') or on the geometry deformed by the step's DEPL ('DEFORMEE', the
// default). MAILLAGE is the result's mesh. INFO=2 prints the range of PRES of each step.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/model/Model.hpp"
#include "solver/operators/MeshOperatorUtil.hpp"
#include "solver/post/DerivedFields.hpp"
#include "solver/post/SkinPressure.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace stella {

namespace {

UserError error(std::string_view key, msg::Args args, const SourceLocation& at) {
  return UserError(msg::make(key, args, at));
}

std::vector<ResultStep*> selectedSteps(Result& r, const std::string& name, const KeywordTree& kw) {
  std::vector<ResultStep*> out;
  if (!kw.has("INST")) { // TOUT_ORDRE
    for (auto& s : r.steps) {
      out.push_back(&s);
    }
    return out;
  }
  for (const double t : kw.reals("INST")) {
    const ResultStep* s = r.stepAtTime(t, kw.real("PRECISION"), kw.text("CRITERE") == "ABSOLU");
    if (s == nullptr) {
      throw error("CALC_PRESSION_1", {{"name", name}, {"t", t}}, kw.locationOf("INST"));
    }
    out.push_back(r.stepNumber(s->number));
  }
  return out;
}

// The skin cells of GROUP_MA; a cell that is not of the skin's dimension is an error.
std::vector<CellId> skinCells(const Mesh& mesh, const KeywordTree& kw) {
  const auto cells = cellsOfGroups(mesh, kw, "GROUP_MA");
  for (const CellId c : cells) {
    if (dimension(mesh.cellType(c)) != mesh.dimension() - 1) {
      throw error(
          mesh.dimension() == 2 ? "CALC_PRESSION_1.skin_2d" : "CALC_PRESSION_1.skin_3d",
          {{"cell", mesh.cellName(c)}, {"type", name(mesh.cellType(c))}, {"dimension", mesh.dimension()}},
          kw.locationOf("GROUP_MA"));
    }
  }
  return cells;
}

std::vector<Point3> coordinates(const Mesh& mesh, const ResultStep& step, bool deformed,
                                const std::string& name, const KeywordTree& kw) {
  std::vector<Point3> x(static_cast<std::size_t>(mesh.nodeCount()));
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    x[static_cast<std::size_t>(n)] = mesh.point(n);
  }
  if (!deformed) {
    return x;
  }
  const Field* depl = step.field("DEPL");
  if (depl == nullptr || depl->support() != FieldSupport::Node) {
    throw error("CALC_PRESSION_1.2", {{"name", name}, {"number", step.number}}, kw.locationOf("GEOMETRIE"));
  }
  for (int d = 0; d < 3; ++d) {
    const auto i = depl->componentIndex(Model::componentName(d));
    if (!i) {
      continue;
    }
    for (std::size_t n = 0; n < x.size(); ++n) {
      if (depl->defined(n, *i)) {
        x[n][static_cast<std::size_t>(d)] += depl->value(n, *i);
      }
    }
  }
  return x;
}

void printRange(OperatorCall& call, const Field& pres, const ResultStep& step) {
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  int count = 0;
  for (std::size_t n = 0; n < pres.entityCount(); ++n) {
    if (pres.defined(n, 0)) {
      low = std::min(low, pres.value(n, 0));
      high = std::max(high, pres.value(n, 0));
      ++count;
    }
  }
  call.session.message() << fmt::format(
      "  CALC_PRESSION: NUME_ORDRE {} (INST {}): PRES on {} node(s), from {} to {}\n", step.number, step.time,
      count, low, high);
}

Value runCalcPression(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  const auto concept_ = kw.conceptValue("RESULTAT");
  auto result = conceptData<Result>(concept_);
  STELLA_ASSERT(result != nullptr, "RESULTAT holds no result");
  auto model = std::dynamic_pointer_cast<Model>(result->model);
  if (!model) {
    throw error("CALC_PRESSION_1.3", {{"name", concept_->name}}, kw.locationOf("RESULTAT"));
  }
  const Mesh& mesh = *meshConceptOf(kw)->mesh;
  if (mesh.nodeCount() != model->mesh->nodeCount() || mesh.cellCount() != model->mesh->cellCount()) {
    throw error("CALC_PRESSION_1.4", {{"name", concept_->name}}, kw.locationOf("MAILLAGE"));
  }
  const auto skin = skinCells(mesh, kw);
  const bool deformed = kw.text("GEOMETRIE") == "DEFORMEE";
  const std::vector<bool> volumes = selectedVolumeCells(*model, {});
  const auto steps = selectedSteps(*result, concept_->name, kw);
  for (ResultStep* step : steps) {
    const Field* sief = step->field("SIEF_ELGA");
    if (sief == nullptr) {
      throw error("CALC_PRESSION_1.5", {{"name", concept_->name}, {"number", step->number}},
                  kw.locationOf("RESULTAT"));
    }
    const Field sigma = averageAtNodes(mesh, extrapolateToCellNodes(*model, *sief, volumes));
    const auto x = coordinates(mesh, *step, deformed, concept_->name, kw);
    auto pres = std::make_shared<Field>(skinPressure(mesh, x, sigma, skin));
    if (kw.integer("INFO") >= 2) {
      printRange(call, *pres, *step);
    }
    step->fields["PRES_NOEU"] = pres;
  }
  call.session.message() << fmt::format(
      "  CALC_PRESSION: PRES_NOEU on {} skin cell(s), {} geometry, stored on {} "
      "step(s) of {}\n",
      skin.size(), deformed ? "deformed" : "initial", steps.size(), concept_->name);
  return call.makeConcept(result);
}

} // namespace

STELLA_OPERATOR("CALC_PRESSION", runCalcPression);

} // namespace stella
