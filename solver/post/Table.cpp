#include "Table.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace stella {

Table::Column& Table::ensureColumn(const std::string& name) {
  for (auto& c : columns_) {
    if (c.name == name) {
      return c;
    }
  }
  columns_.push_back({name, ValueList(rows_)});
  return columns_.back();
}

void Table::addRow(const std::vector<std::pair<std::string, Value>>& cells) {
  for (const auto& [name, value] : cells) {
    ensureColumn(name);
  }
  ++rows_;
  for (auto& c : columns_) {
    c.cells.resize(rows_);
  }
  for (const auto& [name, value] : cells) {
    ensureColumn(name).cells[rows_ - 1] = value;
  }
}

void Table::addColumn(const std::string& name, ValueList cells) {
  rows_ = std::max(rows_, cells.size());
  Column& c = ensureColumn(name);
  c.cells = std::move(cells);
  for (auto& col : columns_) {
    col.cells.resize(rows_);
  }
}

const Table::Column* Table::column(const std::string& name) const {
  for (const auto& c : columns_) {
    if (c.name == name) {
      return &c;
    }
  }
  return nullptr;
}

std::vector<std::string> Table::columnNames() const {
  std::vector<std::string> names;
  for (const auto& c : columns_) {
    names.push_back(c.name);
  }
  return names;
}

namespace {
std::string cellText(const Value& v) {
  if (v.isNone()) {
    return "-";
  }
  if (v.isReal()) {
    return fmt::format("{:.6E}", v.asReal());
  }
  return v.str();
}
} // namespace

std::string Table::format(const std::string& kind, const std::string& separator) const {
  std::string out;
  if (kind == "CSV") {
    for (std::size_t i = 0; i < columns_.size(); ++i) {
      out += (i ? separator : "") + columns_[i].name;
    }
    out += "\n";
    for (std::size_t r = 0; r < rows_; ++r) {
      for (std::size_t i = 0; i < columns_.size(); ++i) {
        out += (i ? separator : "") + cellText(columns_[i].cells[r]);
      }
      out += "\n";
    }
    return out;
  }
  if (kind == "ASTER") {
    out += "#DEBUT_TABLE\n";
  }
  if (!title.empty()) {
    out += "#TITRE " + title + "\n";
  }
  std::vector<std::size_t> widths;
  for (const auto& c : columns_) {
    std::size_t w = std::max<std::size_t>(16, c.name.size());
    for (const auto& v : c.cells) {
      w = std::max(w, cellText(v).size());
    }
    widths.push_back(w);
  }
  auto row = [&](auto cell) {
    std::string line;
    for (std::size_t i = 0; i < columns_.size(); ++i) {
      line += fmt::format(" {:<{}}", cell(i), widths[i]);
    }
    line.erase(line.find_last_not_of(' ') + 1);
    return line + "\n";
  };
  out += row([&](std::size_t i) { return columns_[i].name; });
  for (std::size_t r = 0; r < rows_; ++r) {
    out += row([&](std::size_t i) { return cellText(columns_[i].cells[r]); });
  }
  if (kind == "ASTER") {
    out += "#FIN_TABLE\n";
  }
  return out;
}

} // namespace stella
