#include "Table.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>
#include <string>

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

// "E12.5" -> {'E', 12, 5}; anything else falls back to E12.5.
struct RealFormat {
  char kind = 'E';
  int width = 12;
  int digits = 5;
};

RealFormat parseRealFormat(const std::string& f) {
  RealFormat r;
  if (f.size() < 2 || (f[0] != 'E' && f[0] != 'F' && f[0] != 'G' && f[0] != 'D')) {
    return r;
  }
  const auto dot = f.find('.');
  try {
    r.width = std::stoi(f.substr(1, dot == std::string::npos ? std::string::npos : dot - 1));
    r.digits = dot == std::string::npos ? 0 : std::stoi(f.substr(dot + 1));
    r.kind = f[0] == 'D' ? 'E' : f[0];
  } catch (const std::exception&) {
    return RealFormat{};
  }
  return r;
}

std::string cellText(const Value& v, const RealFormat& f) {
  if (v.isNone()) {
    return "-";
  }
  if (v.isReal()) {
    const double x = v.asReal();
    switch (f.kind) {
    case 'F':
      return fmt::format("{:{}.{}f}", x, f.width, f.digits);
    case 'G':
      return fmt::format("{:{}.{}G}", x, f.width, f.digits);
    default:
      return fmt::format("{:{}.{}E}", x, f.width, f.digits);
    }
  }
  return v.str();
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(' ');
  return b == std::string::npos ? "" : s.substr(b);
}

} // namespace

std::string Table::columnType(const Column& column) const {
  bool real = false;
  std::size_t longest = 0;
  bool text = false;
  for (const auto& v : column.cells) {
    real = real || v.isReal();
    if (v.isString()) {
      text = true;
      longest = std::max(longest, v.asString().size());
    }
  }
  if (text) {
    return longest <= 8 ? "K8" : longest <= 16 ? "K16" : longest <= 24 ? "K24" : "K80";
  }
  return real ? "R" : "I";
}

std::string Table::format(const std::string& kind, const std::string& separator,
                          const std::string& realFormat) const {
  const RealFormat rf = parseRealFormat(realFormat);
  std::string out;
  if (kind == "CSV") {
    for (std::size_t i = 0; i < columns_.size(); ++i) {
      out += (i ? separator : "") + columns_[i].name;
    }
    out += "\n";
    for (std::size_t r = 0; r < rows_; ++r) {
      for (std::size_t i = 0; i < columns_.size(); ++i) {
        out += (i ? separator : "") + trimmed(cellText(columns_[i].cells[r], rf));
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
      w = std::max(w, cellText(v, rf).size());
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
  if (kind == "ASTER") {
    out += row([&](std::size_t i) { return columnType(columns_[i]); });
  }
  for (std::size_t r = 0; r < rows_; ++r) {
    out += row([&](std::size_t i) { return cellText(columns_[i].cells[r], rf); });
  }
  if (kind == "ASTER") {
    out += "#FIN_TABLE\n";
  }
  return out;
}

} // namespace stella
