// POST_RELEVE_T: tables of values of result fields. Implemented: OPERATION='EXTRACTION' on nodal
// fields of a RESULTAT (DEPL, REAC_NODA, FORC_NODA...), either the values per node (NOM_CMP or
// TOUT_CMP; columns NOEUD, COOR_X..., the components) or their sum (RESULTANTE), one row per
// stored step (TOUT_ORDRE, NUME_ORDRE, INST), with INTITULE, RESU, NOM_CHAM, NUME_ORDRE, INST.
// MOYENNE, EXTREMA, CHAM_GD and element fields are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "solver/database/Result.hpp"
#include "solver/model/Selection.hpp"
#include "solver/post/FieldSelection.hpp"
#include "solver/post/Table.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

bool stepWanted(const ResultStep& s, const KeywordTree& a) {
  if (a.has("NUME_ORDRE")) {
    const auto n = a.integers("NUME_ORDRE");
    return std::find(n.begin(), n.end(), s.number) != n.end();
  }
  if (a.has("INST")) {
    const double precision = a.realOr("PRECISION", 1.0e-6);
    const bool absolute = a.textOr("CRITERE", "RELATIF") == "ABSOLU";
    for (double t : a.reals("INST")) {
      if (std::fabs(t - s.time) <= precision * (absolute ? 1.0 : std::max(std::fabs(t), 1.0e-300))) {
        return true;
      }
    }
    return false;
  }
  return true;
}

void extract(const KeywordTree& a, Table& table) {
  for (const char* k : {"CHAM_GD", "MOMENT", "INVARIANT", "ELEM_PRINCIPAUX", "NOEUD_CMP", "NOM_CAS", "FREQ",
                        "LIST_INST", "LIST_ORDRE"}) {
    if (a.has(k)) {
      throw UserError(Diagnostic::fatal("RELEVE_1", fmt::format("POST_RELEVE_T {} is not implemented yet", k),
                                        a.locationOf(k)));
    }
  }
  const auto operations = a.texts("OPERATION");
  for (const auto& op : operations) {
    if (op != "EXTRACTION") {
      throw UserError(Diagnostic::fatal(
                          "RELEVE_1", fmt::format("POST_RELEVE_T OPERATION='{}' is not implemented yet", op),
                          a.locationOf("OPERATION"))
                          .withNote("implemented: OPERATION='EXTRACTION' (values per node, or RESULTANTE)"));
    }
  }
  auto concept_ = a.conceptValue("RESULTAT");
  auto result = conceptData<Result>(concept_);
  STELLA_ASSERT(result != nullptr, "RESULTAT holds no result");
  const Mesh& mesh = *result->mesh;
  const std::string fieldName = a.text("NOM_CHAM");
  const auto nodes = selectNodes(mesh, a);
  bool any = false;
  for (const ResultStep& step : result->steps) {
    if (!stepWanted(step, a)) {
      continue;
    }
    any = true;
    const Field& field = selectField(step, concept_->name, fieldName, a);
    if (field.support() != FieldSupport::Node) {
      throw UserError(
          Diagnostic::fatal(
              "RELEVE_1",
              fmt::format("POST_RELEVE_T on the element field {} is not implemented yet", fieldName),
              a.locationOf("NOM_CHAM"))
              .withNote("compute a nodal field with CALC_CHAMP (e.g. REAC_NODA)"));
    }
    std::vector<std::pair<std::string, Value>> head{
        {"INTITULE", Value(a.text("INTITULE"))},
        {"RESU", Value(concept_->name)},
        {"NOM_CHAM", Value(fieldName)},
        {"NUME_ORDRE", Value(static_cast<std::int64_t>(step.number))},
        {"INST", Value(step.time)}};
    if (a.has("RESULTANTE")) {
      auto row = head;
      for (const auto& cmp : a.texts("RESULTANTE")) {
        const std::size_t c = selectComponent(field, fieldName, cmp, a);
        double sum = 0.0;
        for (NodeId n : nodes) {
          if (field.defined(static_cast<std::size_t>(n), c)) {
            sum += field.value(static_cast<std::size_t>(n), c);
          }
        }
        row.emplace_back(cmp, Value(sum));
      }
      table.addRow(row);
      continue;
    }
    const auto components = a.has("NOM_CMP") ? a.texts("NOM_CMP") : field.components();
    for (NodeId n : nodes) {
      auto row = head;
      row.emplace_back("NOEUD", Value(mesh.nodeName(n)));
      const Point3 x = mesh.point(n);
      row.emplace_back("COOR_X", Value(x[0]));
      row.emplace_back("COOR_Y", Value(x[1]));
      if (mesh.dimension() == 3) {
        row.emplace_back("COOR_Z", Value(x[2]));
      }
      for (const auto& cmp : components) {
        const std::size_t c = selectComponent(field, fieldName, cmp, a);
        row.emplace_back(cmp, field.defined(static_cast<std::size_t>(n), c)
                                  ? Value(field.value(static_cast<std::size_t>(n), c))
                                  : Value());
      }
      table.addRow(row);
    }
  }
  if (!any) {
    throw UserError(Diagnostic::fatal(
        "RESU_1", fmt::format("no stored step of {} matches NUME_ORDRE / INST", concept_->name),
        a.location()));
  }
}

Value runPostReleveT(OperatorCall& call) {
  auto table = std::make_shared<Table>();
  for (const KeywordTree& a : call.keywords.occurrences("ACTION")) {
    extract(a, *table);
  }
  return call.makeConcept(table);
}

} // namespace

STELLA_OPERATOR("POST_RELEVE_T", runPostReleveT);

} // namespace stella
