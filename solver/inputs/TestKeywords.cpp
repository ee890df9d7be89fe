#include "solver/inputs/TestKeywords.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

namespace stella {

namespace {

void refuse(const KeywordTree& kw, const std::string& name, const std::string& why) {
  throw UserError(msg::make("TEST_1", {{"name", name}, {"why", why}}, kw.locationOf(name)));
}

// The single real of VALE_CALC / VALE_CALC_I (or VALE_REFE / VALE_REFE_I).
std::optional<double> singleValue(const KeywordTree& kw, const std::string& realName,
                                  const std::string& intName) {
  for (const std::string& name : {realName, intName}) {
    if (const SimpleKeyword* k = kw.simple(name)) {
      if (k->values.size() != 1) {
        refuse(kw, name, msg::text("TEST_1.f1"));
      }
      return k->values.front().asReal();
    }
  }
  return std::nullopt;
}

} // namespace

ValueTest valueTestFromKeywords(const KeywordTree& kw, double computed, const std::string& legend) {
  for (const std::string name : {"VALE_CALC_C", "VALE_REFE_C", "VALE_CALC_K", "VALE_REFE_K"}) {
    if (kw.has(name)) {
      refuse(kw, name, name.back() == 'C' ? msg::text("TEST_1.f2") : msg::text("TEST_1.f3"));
    }
  }
  ValueTest t;
  t.legend = kw.textOr("LEGENDE", legend);
  t.computed = computed;
  t.valeCalc = singleValue(kw, "VALE_CALC", "VALE_CALC_I");
  t.toleMachine = kw.real("TOLE_MACHINE");
  if (kw.has("REFERENCE")) {
    t.reference = kw.text("REFERENCE");
    t.valeRefe = singleValue(kw, "VALE_REFE", "VALE_REFE_I");
    t.precision = kw.real("PRECISION");
  }
  t.absolute = kw.text("CRITERE") == "ABSOLU";
  t.ordreGrandeur = kw.realOr("ORDRE_GRANDEUR", 1.0);
  return t;
}

} // namespace stella
