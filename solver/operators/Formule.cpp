// FORMULE: a real function written as an expression of its parameters, compiled once
// (FORMULE(VALE='p0*INST', NOM_PARA='INST', p0=p0)); extra keywords bind numeric constants.

#include "interpreter/Diagnostics.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/session/OperatorRegistry.hpp"

namespace stella {

namespace {

Value runFormule(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  if (kw.has("VALE_C")) {
    throw UserError(Diagnostic::fatal(
        "FUNCTION_3", "FORMULE/VALE_C (complex formulas) is not implemented yet", kw.locationOf("VALE_C")));
  }
  std::vector<std::pair<std::string, double>> constants;
  for (const SimpleKeyword& k : kw.simples()) {
    if (k.name == "VALE" || k.name == "NOM_PARA") {
      continue;
    }
    if (k.values.size() != 1 || !k.values.front().isNumber()) {
      throw UserError(Diagnostic::fatal("FUNCTION_6",
                                        "FORMULE: the constant " + k.name +
                                            " must be a number; other kinds of "
                                            "constants are not implemented yet",
                                        k.location));
    }
    constants.emplace_back(k.name, k.values.front().asReal());
  }
  const SimpleKeyword* text = kw.simple("VALE");
  auto f = std::make_shared<FormulaFunction>(kw.text("VALE"), kw.texts("NOM_PARA"), std::move(constants),
                                             text->location);
  f->name = call.resultName;
  return call.makeConcept(f);
}

} // namespace

STELLA_OPERATOR("FORMULE", runFormule);

} // namespace stella
