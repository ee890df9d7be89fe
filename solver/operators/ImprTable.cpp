// IMPR_TABLE: prints a table (FORMAT 'TABLEAU' or 'ASTER'; SEPARATEUR=',' gives CSV) to a unit,
// the result file (unit 8) by default, after FILTRE, NOM_PARA (columns) and TRI (order).

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/TableFilter.hpp"
#include "solver/post/Table.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>

namespace stella {

namespace {

void sortRows(const Table& table, const KeywordTree& sort, std::vector<std::size_t>& rows) {
  std::vector<const Table::Column*> keys;
  for (const auto& name : sort.texts("NOM_PARA")) {
    const Table::Column* c = table.column(name);
    if (c == nullptr) {
      throw UserError(msg::make("TABLE_1.2", {{"name", name}}, sort.locationOf("NOM_PARA")));
    }
    keys.push_back(c);
  }
  bool descending = sort.text("ORDRE") == "DECROISSANT";
  std::stable_sort(rows.begin(), rows.end(), [&](std::size_t a, std::size_t b) {
    for (const auto* c : keys) {
      const Value& x = c->cells[a];
      const Value& y = c->cells[b];
      if (x.isNumber() && y.isNumber() && x.asReal() != y.asReal()) {
        return descending ? x.asReal() > y.asReal() : x.asReal() < y.asReal();
      }
      if (x.isString() && y.isString() && x.asString() != y.asString()) {
        return descending ? x.asString() > y.asString() : x.asString() < y.asString();
      }
    }
    return false;
  });
}

Table selection(const Table& table, const KeywordTree& kw) {
  std::vector<std::size_t> rows = filterRows(table, kw.occurrences("FILTRE"));
  if (const auto& sorts = kw.occurrences("TRI"); !sorts.empty()) {
    sortRows(table, sorts.front(), rows);
  }
  std::vector<std::string> names = kw.has("NOM_PARA") ? kw.texts("NOM_PARA") : table.columnNames();
  Table out;
  out.title = kw.textOr("TITRE", table.title);
  for (const auto& name : names) {
    const Table::Column* c = table.column(name);
    if (c == nullptr) {
      throw UserError(msg::make("TABLE_1.3", {{"name", name}, {"join", fmt::join(table.columnNames(), ", ")}},
                                kw.locationOf("NOM_PARA")));
    }
    ValueList cells;
    for (std::size_t r : rows) {
      cells.push_back(c->cells[r]);
    }
    out.addColumn(name, std::move(cells));
  }
  return out;
}

Value runImprTable(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  const std::string format = kw.text("FORMAT");
  if (format != "TABLEAU" && format != "ASTER") {
    throw UserError(msg::make("TABLE_6", {{"format", format}}, kw.locationOf("FORMAT")));
  }
  auto source = kw.conceptValue("TABLE");
  auto table = conceptData<Table>(source);
  STELLA_ASSERT(table != nullptr, "TABLE holds no table");
  // SEPARATEUR (FORMAT='TABLEAU' only): other than a blank, the table is written as CSV.
  const std::string separator = format == "TABLEAU" ? kw.text("SEPARATEUR") : std::string(" ");
  Table shown = selection(*table, kw);
  const std::string realFormat = kw.text("FORMAT_R");
  std::string text =
      separator != " " ? shown.format("CSV", separator, realFormat) : shown.format(format, " ", realFormat);
  std::int64_t unit = kw.integer("UNITE");
  if (unit == 8) {
    call.session.result() << text << "\n";
  } else if (unit == 6) {
    call.session.message() << text << "\n";
  } else {
    std::ofstream out(call.session.unitPath(static_cast<int>(unit), kw.locationOf("UNITE"), false),
                      std::ios::app);
    out << text << "\n";
  }
  call.session.message() << "  Table " << source->name << " printed to unit " << unit << " ("
                         << shown.rowCount() << " rows)\n";
  return Value();
}

} // namespace

STELLA_OPERATOR("IMPR_TABLE", runImprTable);

} // namespace stella
