// TEST_RESU RESU: tests one value of a result field (at a node, at a cell's Gauss point, or the
// MIN/MAX/SOMM/SOMM_ABS of a component) or a step parameter (PARA), printing OK/NOOK lines.
// Element fields are designated by MAILLE / GROUP_MA and POINT (ELGA: Gauss point; ELNO: local
// node) or, for ELNO fields, NOEUD. CHAM_NO and CHAM_ELEM test a field concept made by
// CREA_CHAMP the same way (headers CHAM_NO / CHAM_ELEM). TYPE_TEST without NOM_CMP reduces every
// component. CARTE, GENE, OBJET, TEST_NAN and MAILLAGE are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/FieldSelection.hpp"
#include "solver/inputs/TestKeywords.hpp"
#include "solver/post/FieldConcept.hpp"
#include "solver/post/TestReport.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

void testParameter(OperatorCall& call, const KeywordTree& occ, const Result& result, const std::string& name,
                   const ResultStep& step) {
  const std::string para = occ.text("PARA");
  auto it = step.parameters.find(para);
  if (it == step.parameters.end()) {
    throw UserError(msg::make("RESU_7", {{"name", name}, {"para", para}, {"number", step.number}},
                              occ.locationOf("PARA")));
  }
  (void)result;
  reportTest(call.testReport(),
             {{"RESULTAT", name}, {"NUME_ORDRE", std::to_string(step.number)}, {"PARA", para}},
             valueTestFromKeywords(occ, it->second, para));
}

// Tests one value of `field` designated by the occurrence (NOM_CMP with a node, a cell's point or
// TYPE_TEST; TYPE_TEST without NOM_CMP reduces every component). `header` starts with what names
// the field (RESULTAT / NUME_ORDRE / NOM_CHAM, or CHAM_NO, or CHAM_ELEM).
void testFieldValue(OperatorCall& call, const KeywordTree& occ, const Mesh& mesh, const Field& field,
                    const std::string& fieldName, std::vector<std::pair<std::string, std::string>> header) {
  const std::string type = occ.textOr("TYPE_TEST", "");
  if (!occ.has("NOM_CMP") && type.empty()) {
    throw UserError(msg::make("RESU_3.2",
                              {{"field_name", fieldName}, {"join", fmt::join(field.components(), ", ")}},
                              occ.location()));
  }
  const std::string cmp = occ.textOr("NOM_CMP", "");
  std::vector<std::size_t> components;
  if (occ.has("NOM_CMP")) {
    components.push_back(selectComponent(field, fieldName, cmp, occ));
  } else {
    for (std::size_t c = 0; c < field.componentCount(); ++c) {
      components.push_back(c);
    }
  }
  const EntitySelection sel = selectEntities(mesh, field, occ);
  double value = 0.0;
  if (!type.empty()) {
    std::vector<double> values;
    for (std::size_t e : sel.entities) {
      for (std::size_t c : components) {
        if (field.defined(e, c)) {
          values.push_back(field.value(e, c));
        }
      }
    }
    if (values.empty()) {
      throw UserError(msg::make("RESU_6", {}, occ.location()));
    }
    value = reduceByTestType(type, values);
    header.emplace_back("TYPE_TEST", type);
    if (!cmp.empty()) {
      header.emplace_back("NOM_CMP", cmp);
    }
  } else {
    header.emplace_back("NOM_CMP", cmp);
    if (!sel.single) {
      throw UserError(msg::make("RESU_4.3", {}, occ.location())
                          .withNote(field.support() == FieldSupport::Node       ? msg::text("RESU_4.n1")
                                    : field.support() == FieldSupport::CellNode ? msg::text("RESU_4.n2")
                                                                                : msg::text("RESU_4.n3")));
    }
    const std::size_t e = sel.entities.front();
    const std::size_t c = components.front();
    if (!field.defined(e, c)) {
      throw UserError(msg::make("RESU_6.2", {{"cmp", cmp}, {"field_name", fieldName}, {"label", sel.label}},
                                occ.location()));
    }
    value = field.value(e, c);
    if (field.support() == FieldSupport::CellNode && !occ.has("POINT")) {
      const auto space = sel.label.find(' '); // "cell node"
      header.emplace_back("MAILLE", sel.label.substr(0, space));
      header.emplace_back("NOEUD", sel.label.substr(space + 1));
    } else if (field.support() == FieldSupport::Node || field.support() == FieldSupport::Cell) {
      header.emplace_back(field.support() == FieldSupport::Node ? "NOEUD" : "MAILLE", sel.label);
    } else {
      const auto cut = sel.label.find(" point "); // "cell point p"
      header.emplace_back("MAILLE", sel.label.substr(0, cut));
      header.emplace_back("POINT", sel.label.substr(cut + 7));
    }
  }
  if (occ.text("VALE_ABS") == "OUI") {
    value = std::fabs(value);
  }
  reportTest(call.testReport(), header, valueTestFromKeywords(occ, value, fieldName));
}

void testResu(OperatorCall& call, const KeywordTree& occ) {
  for (const char* k : {"FREQ", "NUME_MODE", "NOEUD_CMP", "NOM_CAS", "ANGLE", "NOM_VARI"}) {
    if (occ.has(k)) {
      throw UserError(msg::make("TEST_1.2", {{"k", k}}, occ.locationOf(k)));
    }
  }
  auto concept_ = occ.conceptValue("RESULTAT");
  auto result = conceptData<Result>(concept_);
  STELLA_ASSERT(result != nullptr, "RESULTAT holds no result");
  const std::string& name = concept_->name;
  const ResultStep& step = selectStep(*result, name, occ);
  if (occ.has("PARA")) {
    testParameter(call, occ, *result, name, step);
    return;
  }
  const std::string fieldName = occ.text("NOM_CHAM");
  const Field& field = selectField(step, name, fieldName, occ);
  testFieldValue(call, occ, *result->mesh, field, fieldName,
                 {{"RESULTAT", name}, {"NUME_ORDRE", std::to_string(step.number)}, {"NOM_CHAM", fieldName}});
}

// CHAM_NO / CHAM_ELEM: a field concept made by CREA_CHAMP.
void testFieldConcept(OperatorCall& call, const KeywordTree& occ, const std::string& keyword) {
  auto concept_ = occ.conceptValue("CHAM_GD");
  auto data = conceptData<FieldConcept>(concept_);
  STELLA_ASSERT(data != nullptr && data->field != nullptr && data->mesh != nullptr, "CHAM_GD holds no field");
  const bool nodal = data->field->support() == FieldSupport::Node;
  if (nodal != (keyword == "CHAM_NO")) {
    throw UserError(msg::make("RESU_8",
                              {{"name", concept_->name},
                               {"nodal", nodal ? "nodal" : "cell"},
                               {"field_type", data->fieldType},
                               {"nodal_2", nodal ? "CHAM_NO" : "CHAM_ELEM"}},
                              occ.locationOf("CHAM_GD")));
  }
  testFieldValue(call, occ, *data->mesh, *data->field, data->origin, {{keyword, concept_->name}});
}

Value runTestResu(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  if (kw.has("CARTE")) {
    throw UserError(msg::make("TEST_1.3", {}, kw.locationOf("CARTE")));
  }
  for (const char* k : {"GENE", "OBJET", "TEST_NAN", "MAILLAGE"}) {
    if (kw.has(k)) {
      throw UserError(msg::make("TEST_1.4", {{"k", k}}, kw.locationOf(k)));
    }
  }
  for (const char* k : {"CHAM_NO", "CHAM_ELEM"}) {
    for (const KeywordTree& occ : kw.occurrences(k)) {
      testFieldConcept(call, occ, k);
    }
  }
  for (const KeywordTree& occ : kw.occurrences("RESU")) {
    testResu(call, occ);
  }
  return Value();
}

} // namespace

STELLA_OPERATOR("TEST_RESU", runTestResu);

} // namespace stella
