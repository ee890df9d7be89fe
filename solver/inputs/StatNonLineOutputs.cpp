// StatNonLineOutputs: OBSERVATION, SUIVI_DDL, MESURE and AFFICHAGE of STAT_NON_LINE -> the plain
// settings of solver/nonlinear/ (FieldExtraction, Observations, DofMonitor, StepMeasures,
// ConvergenceDisplay).

#include "solver/inputs/StatNonLineOutputs.hpp"

#include "catalog/KeywordTree.hpp"
#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/inputs/Selection.hpp"

#include <fmt/format.h>

namespace stella {

FieldExtraction readFieldExtraction(const KeywordTree& occ, const Mesh& mesh, const std::string& keyword) {
  FieldExtraction e;
  e.at = occ.location();
  e.field = occ.text("NOM_CHAM");
  // The catalogue refuses the other fields (NOM_CHAM implemente=).
  STELLA_ASSERT(
      e.nodal() || FieldExtraction::gaussPointField(e.field),
      fmt::format("{} NOM_CHAM='{}' passed the catalogue but cannot be extracted", keyword, e.field));
  e.components = occ.texts("NOM_CMP");
  e.evalField = occ.text("EVAL_CHAM");
  if (e.nodal()) {
    e.nodes = selectNodes(mesh, occ);
  } else {
    e.cells = selectCells(mesh, occ);
    e.evalPoint = occ.text("EVAL_ELGA");
    for (std::int64_t p : occ.has("POINT") ? occ.integers("POINT") : std::vector<std::int64_t>{}) {
      e.points.push_back(static_cast<int>(p));
    }
  }
  return e;
}

Observations readObservations(const KeywordTree& kw, const Mesh& mesh) {
  std::vector<Observations::Item> items;
  int number = 0;
  for (const KeywordTree& occ : kw.occurrences("OBSERVATION")) {
    ++number;
    Observations::Item item;
    item.what = readFieldExtraction(occ, mesh, "OBSERVATION");
    item.title = occ.textOr("TITRE", fmt::format("OBSERVATION_{}", number));
    item.initial = occ.text("OBSE_ETAT_INIT") == "OUI";
    item.every = static_cast<int>(occ.integerOr("PAS_OBSE", 0));
    if (occ.has("PAS_OBSE") && item.every < 1) {
      throw UserError(msg::make("SNL_21", {}, occ.locationOf("PAS_OBSE")));
    }
    if (occ.has("INST")) {
      item.instants = occ.reals("INST");
    } else if (occ.has("LIST_INST")) {
      auto list = conceptData<RealList>(occ.conceptValue("LIST_INST"));
      STELLA_ASSERT(list != nullptr, "OBSERVATION/LIST_INST holds no listr8");
      item.instants = list->values;
    }
    item.precision = occ.real("PRECISION");
    item.absolute = occ.text("CRITERE") == "ABSOLU";
    items.push_back(std::move(item));
  }
  return Observations(std::move(items));
}

std::unique_ptr<DofMonitor> readDofMonitor(const KeywordTree& kw, const MechanicalSystem& system) {
  if (kw.occurrences("SUIVI_DDL").empty()) {
    return nullptr;
  }
  std::vector<DofMonitor::Item> items;
  for (const KeywordTree& occ : kw.occurrences("SUIVI_DDL")) {
    DofMonitor::Item item{readFieldExtraction(occ, *system.model().mesh, "SUIVI_DDL"), ""};
    if (occ.has("TITRE")) {
      item.title = fmt::format("{}", fmt::join(occ.texts("TITRE"), " "));
    }
    items.push_back(std::move(item));
  }
  return std::make_unique<DofMonitor>(system, std::move(items));
}

StepMeasures readStepMeasures(const KeywordTree& kw) {
  if (!kw.has("MESURE")) {
    return {};
  }
  const KeywordTree& occ = kw.occurrences("MESURE").front();
  const bool keepTable = occ.text("TABLE") == "OUI";
  std::optional<int> unit;
  SourceLocation unitAt;
  if (occ.has("UNITE")) {
    unit = static_cast<int>(occ.integer("UNITE"));
    unitAt = occ.locationOf("UNITE");
  }
  return StepMeasures(keepTable, unit, unitAt);
}

ConvergenceDisplay readConvergenceDisplay(const KeywordTree& kw) {
  ConvergenceDisplay d;
  if (!kw.has("AFFICHAGE")) {
    return d;
  }
  const KeywordTree& occ = kw.occurrences("AFFICHAGE").front();
  d.every = static_cast<int>(occ.integerOr("PAS", 1));
  if (occ.has("UNITE")) {
    d.unit = static_cast<int>(occ.integer("UNITE"));
    d.unitAt = occ.locationOf("UNITE");
  }
  return d;
}

} // namespace stella
