// Observation: OBSERVATION of STAT_NON_LINE into the result's table 'OBSERVATION'.

#include "solver/nonlinear/Observation.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella {

bool Observations::Item::due(int index, double time) const {
  if (index == 0) {
    return initial;
  }
  if (!instants.empty()) {
    return std::any_of(instants.begin(), instants.end(), [&](double t) {
      return std::fabs(t - time) <= (absolute ? precision : precision * std::fabs(t));
    });
  }
  return every <= 1 || index % every == 0;
}

std::vector<std::string> Observations::columnNames() const {
  std::vector<std::string> names{"NOM_OBSERVATION", "TYPE_OBJET", "NOM_SD", "NUME_REUSE", "NUME_OBSE", "INST",
                                 "NOM_CHAM",        "EVAL_CHAM",  "NOM_CMP"};
  auto any = [&](auto predicate) { return std::any_of(items_.begin(), items_.end(), predicate); };
  const auto vale = [](const Item& i) { return i.what.evalField == "VALE"; };
  if (any([&](const Item& i) { return i.what.nodal() && vale(i); })) {
    names.emplace_back("NOEUD");
  }
  if (any([&](const Item& i) { return !i.what.nodal() && vale(i); })) {
    names.emplace_back("MAILLE");
  }
  if (any([](const Item& i) { return !i.what.nodal() && i.what.evalPoint != "VALE"; })) {
    names.emplace_back("EVAL_ELGA");
  }
  if (any([](const Item& i) { return !i.what.nodal() && i.what.evalPoint == "VALE"; })) {
    names.emplace_back("POINT");
  }
  names.emplace_back("VALE");
  return names;
}

void Observations::attach(Result& result) {
  if (items_.empty()) {
    return; // no table without OBSERVATION
  }
  auto it = result.tables.find("OBSERVATION");
  if (it != result.tables.end()) {
    table_ = std::dynamic_pointer_cast<Table>(it->second);
  }
  if (!table_) {
    table_ = std::make_shared<Table>();
    result.tables["OBSERVATION"] = table_;
    reuse_ = 0;
    // code_aster's column order, whatever the first row holds.
    for (const std::string& name : columnNames()) {
      table_->addColumn(name, {});
    }
    return;
  }
  // A continuation: the rows so far keep their NUME_REUSE, the new ones take the next.
  reuse_ = 0;
  if (const Table::Column* c = table_->column("NUME_REUSE")) {
    for (const Value& v : c->cells) {
      if (v.isNumber()) {
        reuse_ = std::max(reuse_, static_cast<int>(v.asInt()) + 1);
      }
    }
  }
}

void Observations::observe(int index, double time,
                           const std::function<const Field*(const std::string&)>& field, const Mesh& mesh) {
  for (const Item& item : items_) {
    if (!item.due(index, time)) {
      continue;
    }
    const Field* f = field(item.what.field);
    if (f == nullptr) {
      throw UserError(msg::make("SNL_20.2", {{"field", item.what.field}}, item.what.at));
    }
    for (const ExtractedValue& v : item.what.extract(*f, mesh)) {
      std::vector<std::pair<std::string, Value>> row{
          {"NOM_OBSERVATION", Value(item.title)},
          {"TYPE_OBJET", Value(std::string("R"))},
          {"NOM_SD", Value(std::string(""))},
          {"NUME_REUSE", Value(static_cast<std::int64_t>(reuse_))},
          {"NUME_OBSE", Value(static_cast<std::int64_t>(table_->rowCount() + 1))},
          {"INST", Value(time)},
          {"NOM_CHAM", Value(item.what.field)},
          {"EVAL_CHAM", Value(item.what.evalField)},
          {"NOM_CMP", Value(v.component)}};
      if (item.what.evalField == "VALE") {
        if (item.what.nodal()) {
          row.emplace_back("NOEUD", Value(v.node));
        } else {
          row.emplace_back("MAILLE", Value(v.cell));
        }
      }
      if (!item.what.nodal()) {
        if (item.what.evalPoint == "VALE") {
          row.emplace_back("POINT", Value(static_cast<std::int64_t>(v.point)));
        } else {
          row.emplace_back("EVAL_ELGA", Value(item.what.evalPoint));
        }
      }
      row.emplace_back("VALE", Value(v.value));
      table_->addRow(row);
    }
  }
}

} // namespace stella
