// RECU_TABLE: a copy of a table attached to a result (NOM_TABLE), as a table concept.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/post/Table.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

Value runRecuTable(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  if (kw.has("NOM_PARA")) {
    throw UserError(msg::make("TABLE_6.2", {}, kw.locationOf("NOM_PARA")));
  }
  auto source = kw.conceptValue("CO");
  auto result = conceptData<Result>(source);
  STELLA_ASSERT(result != nullptr, "RECU_TABLE: CO holds no result");
  const std::string name = kw.text("NOM_TABLE");
  auto it = result->tables.find(name);
  std::vector<std::string> names;
  for (const auto& [n, t] : result->tables) {
    names.push_back("'" + n + "'");
  }
  auto found = it == result->tables.end() ? nullptr : std::dynamic_pointer_cast<Table>(it->second);
  if (!found) {
    throw UserError(
        msg::make("TABLE_7", {{"name", source->name}, {"name_2", name}}, kw.locationOf("NOM_TABLE"))
            .withNote(names.empty() ? msg::text("TABLE_7.n1")
                                    : msg::text("TABLE_7.n2", {{"join", fmt::join(names, ", ")}})));
  }
  auto table = std::make_shared<Table>(*found);
  if (kw.has("TITRE")) {
    table->title = kw.text("TITRE");
  }
  return call.makeConcept(table);
}

} // namespace

STELLA_OPERATOR("RECU_TABLE", runRecuTable);

} // namespace stella
