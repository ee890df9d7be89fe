// The sweep table: CSV in and out, Markdown, Pareto front.

#include "SweepTable.hpp"
#include "SweepSpec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>

namespace stella::sweep {

int Table::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

std::string Table::at(std::size_t row, const std::string& name) const {
  const int c = column(name);
  return c < 0 || static_cast<std::size_t>(c) >= rows[row].size() ? std::string() : rows[row][c];
}

void Table::set(std::size_t row, const std::string& name, const std::string& value) {
  int c = column(name);
  if (c < 0) {
    header.push_back(name);
    c = static_cast<int>(header.size()) - 1;
  }
  for (auto& r : rows) {
    r.resize(header.size());
  }
  rows[row][c] = value;
}

std::string formatNumber(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

std::vector<std::size_t> paretoFront(const std::vector<double>& time, const std::vector<double>& error,
                                     const std::vector<bool>& eligible) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (!eligible[i]) {
      continue;
    }
    bool dominated = false;
    for (std::size_t j = 0; j < time.size() && !dominated; ++j) {
      dominated = j != i && eligible[j] && time[j] <= time[i] && error[j] <= error[i] &&
                  (time[j] < time[i] || error[j] < error[i]);
    }
    if (!dominated) {
      front.push_back(i);
    }
  }
  std::sort(front.begin(), front.end(),
            [&](std::size_t a, std::size_t b) { return time[a] != time[b] ? time[a] < time[b] : a < b; });
  return front;
}

namespace {

bool number(const std::string& text, double& value) {
  if (text.empty()) {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) {
    return s;
  }
  std::string out = "\"";
  for (const char c : s) {
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return out + "\"";
}

std::string markdownCell(const std::string& s) {
  std::string out;
  for (const char c : s) {
    out += c == '|' ? std::string("\\|") : std::string(1, c);
  }
  return out;
}

} // namespace

// The time of the front: the column time_s (wall or CPU, as the sweep file says), else wall_s.
static std::string timeColumn(const Table& table) {
  return table.column("time_s") >= 0 ? "time_s" : "wall_s";
}

std::vector<std::size_t> markParetoFront(Table& table) {
  const std::size_t n = table.rows.size();
  std::vector<double> time(n, 0.0);
  std::vector<double> error(n, 0.0);
  std::vector<bool> eligible(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    eligible[i] = table.at(i, "finished") == "yes" && number(table.at(i, timeColumn(table)), time[i]) &&
                  number(table.at(i, "error"), error[i]);
  }
  const auto front = paretoFront(time, error, eligible);
  for (std::size_t i = 0; i < n; ++i) {
    table.set(i, "pareto", std::find(front.begin(), front.end(), i) != front.end() ? "yes" : "");
  }
  if (n == 0 && table.column("pareto") < 0) {
    table.header.push_back("pareto");
  }
  return front;
}

std::string toCsv(const Table& table) {
  std::string out;
  auto line = [&](const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
      out += (i ? "," : "") + csvField(fields[i]);
    }
    out += "\n";
  };
  line(table.header);
  for (const auto& r : table.rows) {
    line(r);
  }
  return out;
}

Table fromCsv(const std::string& text) {
  std::vector<std::vector<std::string>> records(1);
  std::string field;
  bool quoted = false;
  int lineNumber = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      records.back().push_back(field);
      field.clear();
    } else if (c == '\n') {
      records.back().push_back(field);
      field.clear();
      records.emplace_back();
      ++lineNumber;
    } else if (c != '\r') {
      field += c;
    }
  }
  if (quoted) {
    throw SweepError("sweep.csv: a quoted field is not closed (line " + std::to_string(lineNumber) + ")");
  }
  if (!field.empty() || !records.back().empty()) {
    records.back().push_back(field);
  } else {
    records.pop_back();
  }
  if (records.empty() || records.front().empty()) {
    throw SweepError("sweep.csv: no header line");
  }
  Table table{records.front(), {}};
  for (std::size_t r = 1; r < records.size(); ++r) {
    if (records[r].size() != table.header.size()) {
      throw SweepError("sweep.csv:" + std::to_string(r + 1) + ": " + std::to_string(records[r].size()) +
                       " fields where the header has " + std::to_string(table.header.size()));
    }
    table.rows.push_back(records[r]);
  }
  return table;
}

std::string toMarkdown(const Table& table, const std::vector<std::size_t>& front) {
  std::vector<std::string> shown{"run",       "label",       "status",      "wall_s",
                                 "cpu_s",     "peak_mem_mb", "newton_iter", "contact_iter",
                                 "geom_iter", "snl_total_s", "error"};
  for (const auto& h : table.header) {
    if (h.rfind("err:", 0) == 0) {
      shown.push_back(h);
    }
  }
  shown.push_back("pareto");
  std::string out = "|";
  std::string rule = "|";
  for (const auto& h : shown) {
    out += " " + markdownCell(h) + " |";
    rule += "---|";
  }
  out += "\n" + rule + "\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    out += "|";
    for (const auto& h : shown) {
      out += " " + markdownCell(table.at(r, h)) + " |";
    }
    out += "\n";
  }
  // The test the error is of: one for the whole table, or each run's largest.
  std::string of;
  bool oneTest = true;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const std::string name = table.at(r, "error_of");
    oneTest = oneTest && (name.empty() || of.empty() || name == of);
    of = name.empty() ? of : name;
  }
  of = oneTest ? of : std::string();
  const std::string timeOf = table.rows.empty() ? std::string() : table.at(0, "time_of");
  out +=
      "\nPareto front (" +
      (oneTest ? "error" + (of.empty() ? std::string() : " of `" + of + "`") : "largest error of each run") +
      " against the median " + (timeOf == "cpu" ? "CPU" : "wall") +
      " time; no run is both faster and more accurate than these):\n\n";
  if (front.empty()) {
    out += "- none: no run finished with a reference test.\n";
  }
  for (const std::size_t i : front) {
    out += "- error " + table.at(i, "error") +
           (oneTest ? std::string() : " (" + table.at(i, "error_of") + ")") + ": **" + table.at(i, "label") +
           "**, " + table.at(i, timeColumn(table)) + " s\n";
  }
  return out;
}

} // namespace stella::sweep
