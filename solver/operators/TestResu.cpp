// TEST_RESU RESU: tests one value of a result field (at a node, at a cell's Gauss point, or the
// MIN/MAX/SOMM/SOMM_ABS of a component) or a step parameter (PARA), printing OK/NOOK lines.
// Element fields are designated by MAILLE / GROUP_MA and POINT (ELGA: Gauss point; ELNO: local
// node) or, for ELNO fields, NOEUD. CHAM_NO, CHAM_ELEM and CARTE are refused as not implemented
// yet: no command of the catalogue makes such a concept (CREA_CHAMP is not there); the other
// forms are refused likewise.

#include "interpreter/Diagnostics.hpp"
#include "solver/post/FieldSelection.hpp"
#include "solver/post/TestKeywords.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

void testParameter(OperatorCall& call, const KeywordTree& occ, const Result& result, const std::string& name,
                   const ResultStep& step) {
  const std::string para = occ.text("PARA");
  auto it = step.parameters.find(para);
  if (it == step.parameters.end()) {
    throw UserError(Diagnostic::fatal(
        "RESU_7", fmt::format("result {} has no parameter {} at NUME_ORDRE {}", name, para, step.number),
        occ.locationOf("PARA")));
  }
  (void)result;
  reportTest(call.session, {{"RESULTAT", name}, {"NUME_ORDRE", std::to_string(step.number)}, {"PARA", para}},
             valueTestFromKeywords(occ, it->second, para));
}

void testResu(OperatorCall& call, const KeywordTree& occ) {
  for (const char* k : {"FREQ", "NUME_MODE", "NOEUD_CMP", "NOM_CAS", "ANGLE", "NOM_VARI"}) {
    if (occ.has(k)) {
      throw UserError(Diagnostic::fatal("TEST_1", fmt::format("TEST_RESU RESU {} is not implemented yet", k),
                                        occ.locationOf(k)));
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
  if (!occ.has("NOM_CMP")) {
    throw UserError(
        Diagnostic::fatal("RESU_3", "NOM_CMP is needed to test a field value", occ.location())
            .withNote(fmt::format("components of {}: {}", fieldName, fmt::join(field.components(), ", "))));
  }
  const std::string cmp = occ.text("NOM_CMP");
  const std::size_t c = selectComponent(field, fieldName, cmp, occ);
  const EntitySelection sel = selectEntities(*result->mesh, field, occ);
  const std::string type = occ.textOr("TYPE_TEST", "");
  double value = 0.0;
  std::vector<std::pair<std::string, std::string>> header{{"RESULTAT", name},
                                                          {"NUME_ORDRE", std::to_string(step.number)},
                                                          {"NOM_CHAM", fieldName},
                                                          {"NOM_CMP", cmp}};
  if (!type.empty()) {
    value = reduceValues(field, c, sel.entities, type, occ);
    header.emplace_back("TYPE_TEST", type);
  } else {
    if (!sel.single) {
      throw UserError(
          Diagnostic::fatal("RESU_4", "the keywords designate several values; one is needed", occ.location())
              .withNote(field.support() == FieldSupport::Node
                            ? "give NOEUD or a GROUP_NO of one node, or TYPE_TEST"
                        : field.support() == FieldSupport::CellNode
                            ? "give MAILLE (or a GROUP_MA of one cell) and NOEUD (or POINT), or TYPE_TEST"
                            : "give MAILLE (or a GROUP_MA of one cell) and POINT, or TYPE_TEST"));
    }
    const std::size_t e = sel.entities.front();
    if (!field.defined(e, c)) {
      throw UserError(Diagnostic::fatal(
          "RESU_6", fmt::format("component {} of {} has no value at {}", cmp, fieldName, sel.label),
          occ.location()));
    }
    value = field.value(e, c);
    if (field.support() == FieldSupport::CellNode && !occ.has("POINT")) {
      const auto space = sel.label.find(' '); // "cell node"
      header.emplace_back("MAILLE", sel.label.substr(0, space));
      header.emplace_back("NOEUD", sel.label.substr(space + 1));
    } else {
      header.emplace_back(field.support() == FieldSupport::Node ? "NOEUD" : "MAILLE", sel.label);
    }
  }
  if (occ.textOr("VALE_ABS", "NON") == "OUI") {
    value = std::fabs(value);
  }
  reportTest(call.session, header, valueTestFromKeywords(occ, value, fieldName));
}

Value runTestResu(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  for (const char* k : {"CHAM_NO", "CHAM_ELEM", "CARTE"}) {
    if (kw.has(k)) {
      throw UserError(
          Diagnostic::fatal("TEST_1", fmt::format("TEST_RESU {} is not implemented yet", k), kw.locationOf(k))
              .withNote(
                  "no command of stella makes a field concept (cham_no, cham_elem, carte) yet: CREA_CHAMP "
                  "is not in the catalogue. Test the field inside its result with "
                  "RESU=_F(RESULTAT=..., NOM_CHAM='SIEF_NOEU', NOM_CMP=..., NOEUD=...), or "
                  "NOM_CHAM='SIEF_ELNO' with MAILLE and NOEUD"));
    }
  }
  for (const char* k : {"GENE", "OBJET", "TEST_NAN", "MAILLAGE"}) {
    if (kw.has(k)) {
      throw UserError(
          Diagnostic::fatal("TEST_1", fmt::format("TEST_RESU {} is not implemented yet", k), kw.locationOf(k))
              .withNote("test result fields with RESU=_F(RESULTAT=..., NOM_CHAM=..., NOM_CMP=...)"));
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
