// CREA_CHAMP: a field concept (cham_no, cham_elem) extracted from a result (OPERATION='EXTR',
// RESULTAT, NOM_CHAM, NUME_ORDRE or INST with CRITERE / PRECISION, the last step when neither is
// given). TYPE_CHAM must name the field's support and quantity (DEPL is NOEU_DEPL_R, SIEF_ELGA is
// ELGA_SIEF_R, SIEF_ELNO is ELNO_SIEF_R...), as code_aster requires. The other operations (AFFE,
// ASSE, COMB, EVAL, DISC, NORMALE, R2C, C2R), the other sources of EXTR and the extreme over
// steps (TYPE_MAXI) are refused by name as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/FieldSelection.hpp"
#include "solver/post/FieldConcept.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

[[noreturn]] void notImplemented(const KeywordTree& kw, const std::string& keyword, const std::string& what,
                                 const std::string& note) {
  throw UserError(msg::make("CREA_1", {{"what", what}}, kw.locationOf(keyword)).withNote(note));
}

void refuseUnsupported(const KeywordTree& kw) {
  // OPERATION other than EXTR, TYPE_MAXI, FREQ, NUME_MODE, NOEUD_CMP, NOM_CAS, ANGLE and
  // INTERPOL='LIN' are refused by the catalogue (implemente=, non_implemente=).
  for (const char* k : {"MAILLAGE", "TABLE", "CARA_ELEM", "CHARGE", "CHAM_MATER"}) {
    if (kw.has(k) && !kw.has("RESULTAT")) {
      notImplemented(kw, k, msg::text("CREA_1.f1", {{"k", k}}), msg::text("CREA_1.f3"));
    }
  }
  if (kw.text("TYPE_CHAM").rfind("CART_", 0) == 0) {
    notImplemented(kw, "TYPE_CHAM", msg::text("CREA_1.f2", {{"text", kw.text("TYPE_CHAM")}}),
                   msg::text("CREA_1.f4"));
  }
}

// TYPE_CHAM must name the support and the quantity of the stored field.
void checkType(const KeywordTree& kw, const Field& field, const std::string& fieldName) {
  const std::string asked = kw.text("TYPE_CHAM");
  const std::string actual = fieldTypeName(field);
  if (asked == actual) {
    return;
  }
  const bool sameSupport = asked.substr(0, 4) == actual.substr(0, 4);
  throw UserError(msg::make("CREA_2", {{"asked", asked}, {"field_name", fieldName}, {"actual", actual}},
                            kw.locationOf("TYPE_CHAM"))
                      .withNote(sameSupport ? msg::text("CREA_2.n1", {{"actual", actual}})
                                            : msg::text("CREA_2.n2", {{"actual", actual},
                                                                      {"substr", asked.substr(0, 4)}})));
}

Value runCreaChamp(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  refuseUnsupported(kw);
  const auto concept_ = kw.conceptValue("RESULTAT");
  const auto result = conceptData<Result>(concept_);
  STELLA_ASSERT(result != nullptr, "RESULTAT holds no result");
  const bool absolute = kw.text("CRITERE") == "ABSOLU";
  const ResultStep& step = selectStep(*result, concept_->name, kw, kw.real("PRECISION"), absolute);
  const std::string fieldName = kw.text("NOM_CHAM");
  const Field& field = selectField(step, concept_->name, fieldName, kw);
  checkType(kw, field, fieldName);
  auto data = std::make_shared<FieldConcept>();
  data->field = std::make_shared<const Field>(field); // a copy: later changes of the result do not reach it
  data->mesh = result->mesh;
  data->fieldType = fieldTypeName(field);
  data->origin = fieldName;
  call.session.message() << fmt::format("CREA_CHAMP: {} = {} {} of {} at NUME_ORDRE {} (INST {})\n",
                                        call.resultName, data->fieldType, fieldName, concept_->name,
                                        step.number, step.time);
  return call.makeConcept(data);
}

} // namespace

STELLA_OPERATOR("CREA_CHAMP", runCreaChamp);

} // namespace stella
