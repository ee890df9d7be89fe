// CREA_TABLE: a table from lists of values (LISTE=_F(PARA=..., LISTE_R/LISTE_I/LISTE_K=...)).

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/post/Table.hpp"
#include "solver/session/OperatorRegistry.hpp"

namespace stella {

namespace {

Value runCreaTable(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  if (kw.has("FONCTION")) {
    throw UserError(msg::make("TABLE_4", {}, kw.locationOf("FONCTION")));
  }
  auto table = std::make_shared<Table>();
  table->title = kw.textOr("TITRE", "");
  for (const KeywordTree& column : kw.occurrences("LISTE")) {
    const SimpleKeyword* values = column.simple("LISTE_R");
    if (values == nullptr) {
      values = column.simple("LISTE_I");
    }
    if (values == nullptr) {
      values = column.simple("LISTE_K");
    }
    STELLA_ASSERT(values != nullptr, "the catalogue guarantees one of LISTE_I/LISTE_R/LISTE_K");
    ValueList cells = values->values;
    if (const SimpleKeyword* lines = column.simple("NUME_LIGN")) {
      if (lines->values.size() != cells.size()) {
        throw UserError(msg::make("TABLE_5",
                                  {{"values_count", std::to_string(lines->values.size())},
                                   {"cells_count", std::to_string(cells.size())}},
                                  column.locationOf("NUME_LIGN")));
      }
      ValueList placed;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        std::int64_t line = lines->values[i].asInt();
        if (line < 1) {
          throw UserError(msg::make("TABLE_5.2", {}, column.locationOf("NUME_LIGN")));
        }
        if (placed.size() < static_cast<std::size_t>(line)) {
          placed.resize(static_cast<std::size_t>(line));
        }
        placed[static_cast<std::size_t>(line - 1)] = cells[i];
      }
      cells = std::move(placed);
    }
    table->addColumn(column.text("PARA"), std::move(cells));
  }
  return call.makeConcept(table);
}

} // namespace

STELLA_OPERATOR("CREA_TABLE", runCreaTable);

} // namespace stella
