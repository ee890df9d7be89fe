// The grid of a sweep and the substitution of parameter values into command files.

#include "SweepGrid.hpp"

#include <algorithm>
#include <sstream>

namespace stella::sweep {

std::vector<std::string> parameterColumns(const SweepSpec& spec) {
  std::vector<std::string> columns;
  for (const auto& p : spec.vary) {
    columns.push_back(p.name);
  }
  for (const auto& s : spec.series) {
    for (const auto& [name, value] : s.settings) {
      if (std::find(columns.begin(), columns.end(), name) == columns.end()) {
        columns.push_back(name);
      }
    }
  }
  return columns;
}

namespace {

std::string valueOf(const std::vector<Setting>& settings, const std::string& name) {
  for (const auto& [n, v] : settings) {
    if (n == name) {
      return v;
    }
  }
  return {};
}

std::string unquoted(const std::string& v) {
  if (v.size() >= 2 && (v.front() == '\'' || v.front() == '"') && v.back() == v.front()) {
    return v.substr(1, v.size() - 2);
  }
  return v;
}

} // namespace

std::vector<RunPoint> expandGrid(const SweepSpec& spec) {
  const auto columns = parameterColumns(spec);
  std::vector<Series> series = spec.series;
  if (series.empty()) {
    series.push_back(Series{"study", {}, 0, {}});
  }
  std::size_t combinations = 1;
  for (const auto& p : spec.vary) {
    combinations *= p.values.size();
  }
  std::vector<RunPoint> points;
  for (const auto& s : series) {
    for (std::size_t k = 0; k < combinations; ++k) {
      std::vector<Setting> chosen = s.settings;
      std::string label;
      std::size_t rest = k;
      for (auto p = spec.vary.rbegin(); p != spec.vary.rend(); ++p) {
        const std::string& v = p->values[rest % p->values.size()];
        rest /= p->values.size();
        chosen.emplace_back(p->name, v);
      }
      RunPoint point;
      point.index = static_cast<int>(points.size()) + 1;
      point.series = spec.seriesParameter.empty() ? s.name : unquoted(valueOf(chosen, spec.seriesParameter));
      // Without series, the label is the values alone ("N=8", not "study N=8").
      const bool namedSeries = !spec.series.empty() || !spec.seriesParameter.empty();
      label = namedSeries ? point.series : std::string();
      for (const auto& p : spec.vary) {
        if (p.name != spec.seriesParameter) {
          label += (label.empty() ? "" : " ") + p.name + "=" + unquoted(valueOf(chosen, p.name));
        }
      }
      point.label = label.empty() ? point.series : label;
      for (const auto& c : columns) {
        point.settings.emplace_back(c, valueOf(chosen, c));
      }
      points.push_back(std::move(point));
    }
  }
  return points;
}

std::string substituteAssignments(const std::string& text, const std::vector<Setting>& settings,
                                  std::set<std::string>& used) {
  std::istringstream in(text);
  std::string line;
  std::string out;
  bool parameters = true; // the lines before DEBUT() (or POURSUITE()): past it, a name is a concept's
  while (std::getline(in, line)) {
    parameters = parameters && line.rfind("DEBUT(", 0) != 0 && line.rfind("POURSUITE(", 0) != 0;
    for (const auto& [name, value] : settings) {
      if (!parameters || value.empty() || line.compare(0, name.size(), name) != 0) {
        continue;
      }
      const auto eq = line.find_first_not_of(" \t", name.size());
      if (eq != std::string::npos && line[eq] == '=' && (eq + 1 == line.size() || line[eq + 1] != '=')) {
        line = name + " = " + value + "  # set by stella sweep";
        used.insert(name);
        break;
      }
    }
    out += line + "\n";
  }
  return out;
}

std::string substituteBraces(const std::string& command, const std::vector<Setting>& settings,
                             const std::string& meshPath, std::set<std::string>& used) {
  std::string out;
  std::size_t i = 0;
  while (i < command.size()) {
    const auto open = command.find('{', i);
    if (open == std::string::npos) {
      break;
    }
    const auto close = command.find('}', open);
    if (close == std::string::npos) {
      break;
    }
    out += command.substr(i, open - i);
    const std::string name = command.substr(open + 1, close - open - 1);
    if (name == "mesh") {
      out += meshPath;
    } else {
      const auto it =
          std::find_if(settings.begin(), settings.end(), [&](const Setting& s) { return s.first == name; });
      if (it == settings.end() || it->second.empty()) {
        throw SweepError("the command uses {" + name + "}, which is no parameter of this run");
      }
      out += unquoted(it->second);
      used.insert(name);
    }
    i = close + 1;
  }
  return out + command.substr(i);
}

} // namespace stella::sweep
