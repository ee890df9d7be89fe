#include "solver/inputs/TableFilter.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

// Whether a cell equals the filter's real VALE. The catalogue gives PRECISION and CRITERE to every
// FILTRE of TEST_TABLE and to CRIT_COMP='EQ' and 'NE' of IMPR_TABLE's: without them (IMPR_TABLE's
// LT, GT, LE, GE) the comparison is exact.
bool realEquals(double a, double b, const KeywordTree& f) {
  if (!f.has("PRECISION")) {
    return a == b;
  }
  const double tolerance = f.real("PRECISION");
  const bool absolute = f.text("CRITERE") == "ABSOLU";
  const double diff = std::fabs(a - b);
  return absolute ? diff <= tolerance : diff <= tolerance * std::fabs(b);
}

// Compares a cell with the filter's value: <0, 0 or >0, or nullopt when not comparable.
std::optional<int> compareCell(const Value& cell, const KeywordTree& f) {
  if (cell.isNone()) {
    return std::nullopt;
  }
  if (f.has("VALE_K")) {
    if (!cell.isString()) {
      return std::nullopt;
    }
    int c = cell.asString().compare(f.text("VALE_K"));
    return c < 0 ? -1 : (c > 0 ? 1 : 0);
  }
  if (!cell.isNumber()) {
    return std::nullopt;
  }
  double x = cell.asReal();
  double target = f.has("VALE") ? f.real("VALE") : static_cast<double>(f.integer("VALE_I"));
  if (f.has("VALE") && realEquals(x, target, f)) {
    return 0;
  }
  return x < target ? -1 : (x > target ? 1 : 0);
}

bool keepByComparison(const std::string& crit, std::optional<int> c) {
  if (!c) {
    return false;
  }
  if (crit == "EQ") {
    return *c == 0;
  }
  if (crit == "NE") {
    return *c != 0;
  }
  if (crit == "LT") {
    return *c < 0;
  }
  if (crit == "GT") {
    return *c > 0;
  }
  if (crit == "LE") {
    return *c <= 0;
  }
  return *c >= 0; // GE
}

std::vector<std::size_t> applyFilter(const Table::Column& col, const std::vector<std::size_t>& rows,
                                     const KeywordTree& f) {
  const std::string crit = f.text("CRIT_COMP");
  std::vector<std::size_t> kept;
  if (crit == "VIDE" || crit == "NON_VIDE") {
    for (std::size_t r : rows) {
      if (col.cells[r].isNone() == (crit == "VIDE")) {
        kept.push_back(r);
      }
    }
    return kept;
  }
  if (crit.rfind("MAXI", 0) == 0 || crit.rfind("MINI", 0) == 0) {
    bool useAbs = crit.size() > 4;
    bool max = crit.rfind("MAXI", 0) == 0;
    std::optional<double> best;
    for (std::size_t r : rows) {
      if (col.cells[r].isNumber()) {
        double x = useAbs ? std::fabs(col.cells[r].asReal()) : col.cells[r].asReal();
        if (!best || (max ? x > *best : x < *best)) {
          best = x;
        }
      }
    }
    for (std::size_t r : rows) {
      if (best && col.cells[r].isNumber()) {
        double x = useAbs ? std::fabs(col.cells[r].asReal()) : col.cells[r].asReal();
        if (x == *best) {
          kept.push_back(r);
        }
      }
    }
    return kept;
  }
  if (f.has("VALE_C")) {
    throw UserError(msg::make("TABLE_2", {}, f.locationOf("VALE_C")));
  }
  for (std::size_t r : rows) {
    if (keepByComparison(crit, compareCell(col.cells[r], f))) {
      kept.push_back(r);
    }
  }
  return kept;
}

} // namespace

std::vector<std::size_t> filterRows(const Table& table, const std::vector<KeywordTree>& filters) {
  std::vector<std::size_t> rows(table.rowCount());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    rows[r] = r;
  }
  for (const auto& f : filters) {
    const std::string para = f.text("NOM_PARA");
    const Table::Column* col = table.column(para);
    if (col == nullptr) {
      throw UserError(msg::make("TABLE_1", {{"para", para}, {"join", fmt::join(table.columnNames(), ", ")}},
                                f.locationOf("NOM_PARA")));
    }
    rows = applyFilter(*col, rows, f);
  }
  return rows;
}

} // namespace stella
