// FORMULE: a real function written as an expression of its parameters, compiled once
// (FORMULE(VALE='p0*INST', NOM_PARA='INST', p0=p0)); extra keywords bind numeric constants.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/session/OperatorRegistry.hpp"

namespace stella {

namespace {

// Where the value of `NAME = value` starts, from the place of NAME (the keyword's own location
// when the line does not read NAME=).
SourceLocation valueAfter(const SourceLocation& keyword, const std::string& name) {
  if (!keyword.known()) {
    return keyword;
  }
  const std::string_view line = keyword.file->line(keyword.line);
  std::size_t i = static_cast<std::size_t>(keyword.column - 1);
  if (line.substr(i, name.size()) != name) {
    return keyword;
  }
  i += name.size();
  auto skipBlanks = [&] {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) {
      ++i;
    }
  };
  skipBlanks();
  if (i >= line.size() || line[i] != '=') {
    return keyword;
  }
  ++i;
  skipBlanks();
  SourceLocation value = keyword;
  value.column = static_cast<int>(i + 1);
  return value;
}

Value runFormule(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  if (kw.has("VALE_C")) {
    throw UserError(msg::make("FUNCTION_3.2", {}, kw.locationOf("VALE_C")));
  }
  std::vector<std::pair<std::string, double>> constants;
  for (const SimpleKeyword& k : kw.simples()) {
    if (k.name == "VALE" || k.name == "NOM_PARA") {
      continue;
    }
    if (k.values.size() != 1 || !k.values.front().isNumber()) {
      throw UserError(msg::make("FUNCTION_6", {{"name", k.name}}, k.location));
    }
    constants.emplace_back(k.name, k.values.front().asReal());
  }
  const SimpleKeyword* text = kw.simple("VALE");
  // errors of the formula point inside the string literal, when it is written there verbatim
  const SourceLocation origin = valueAfter(text->location, text->name);
  auto f =
      std::make_shared<FormulaFunction>(kw.text("VALE"), kw.texts("NOM_PARA"), std::move(constants), origin);
  f->name = call.resultName;
  return call.makeConcept(f);
}

} // namespace

STELLA_OPERATOR("FORMULE", runFormule);

} // namespace stella
