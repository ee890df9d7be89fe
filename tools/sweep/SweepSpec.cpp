// The sweep file parser: `key = value` lines, then [vary] and [series] sections.

#include "SweepSpec.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <set>
#include <sstream>

namespace stella::sweep {

namespace {

const char* const knownKeys =
    "study, comm, repeats, timeout, time, error, mesh, mesh_unit, mesh_size, series";

[[noreturn]] void fail(const SweepSpec& spec, int line, const std::string& what) {
  std::string where = spec.file.empty() ? std::string("--vary") : spec.file.string();
  if (line > 0) {
    where += ":" + std::to_string(line);
  }
  throw SweepError(where + ": " + what);
}

// The text before a `#` that is outside quotes.
std::string withoutComment(const std::string& line) {
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote != 0) {
      quote = c == quote ? 0 : quote;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '#') {
      return line.substr(0, i);
    }
  }
  return line;
}

bool isName(const std::string& s) {
  if (s.empty() || (std::isalpha(static_cast<unsigned char>(s[0])) == 0 && s[0] != '_')) {
    return false;
  }
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; });
}

// "NAME = rest" -> (NAME, rest); fails unless NAME is a name.
Setting splitAssignment(const SweepSpec& spec, int line, const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) {
    fail(spec, line, "expected NAME = VALUE, got '" + text + "'");
  }
  Setting s{trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
  if (!isName(s.first)) {
    fail(spec, line, "'" + s.first + "' is not a parameter name (letters, digits, _)");
  }
  if (s.second.empty()) {
    fail(spec, line, "no value after '" + s.first + " ='");
  }
  return s;
}

int positiveInteger(const SweepSpec& spec, int line, const std::string& key, const std::string& text) {
  int value = 0;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size() || value < 1) {
    fail(spec, line, key + " expects a positive integer, got '" + text + "'");
  }
  return value;
}

void setKey(SweepSpec& spec, int line, const Setting& kv) {
  const auto folder = spec.file.parent_path();
  const auto& [key, value] = kv;
  if (key == "study") {
    spec.study = std::filesystem::absolute(folder / value).lexically_normal();
  } else if (key == "comm") {
    spec.comm = std::filesystem::absolute(folder / value).lexically_normal();
  } else if (key == "repeats") {
    spec.repeats = positiveInteger(spec, line, key, value);
  } else if (key == "timeout") {
    spec.timeout = positiveInteger(spec, line, key, value);
  } else if (key == "time") {
    if (value != "wall" && value != "cpu") {
      fail(spec, line, "time is wall or cpu, got '" + value + "'");
    }
    spec.time = value;
  } else if (key == "error") {
    spec.error = value;
  } else if (key == "mesh") {
    spec.meshCommand = value;
  } else if (key == "mesh_unit") {
    spec.meshUnit = positiveInteger(spec, line, key, value);
  } else if (key == "mesh_size") {
    spec.meshSize = value;
  } else if (key == "series") {
    spec.seriesParameter = value;
  } else {
    fail(spec, line, "unknown key '" + key + "' (known: " + knownKeys + "; parameters go under [vary])");
  }
}

Parameter parseVary(const SweepSpec& spec, int line, const std::string& text) {
  auto [name, values] = splitAssignment(spec, line, text);
  Parameter p{name, splitTopLevel(values, ','), line};
  for (const auto& v : p.values) {
    if (v.empty()) {
      fail(spec, line, "an empty value in the list of " + name);
    }
  }
  return p;
}

// "label: NAME = value; NAME = value"
Series parseSeries(const SweepSpec& spec, int line, const std::string& text) {
  const auto colon = text.find(':');
  if (colon == std::string::npos || trim(text.substr(0, colon)).empty()) {
    fail(spec, line, "a series is 'NAME: PARAMETER = value; ...', got '" + text + "'");
  }
  Series s{trim(text.substr(0, colon)), {}, line, {}};
  const std::string rest = trim(text.substr(colon + 1));
  if (!rest.empty() && rest.front() == '!') {
    s.command = trim(rest.substr(1));
    if (s.command.find("{out}") == std::string::npos) {
      fail(spec, line,
           "the command of external series '" + s.name +
               "' must write its results to {out}, e.g. '! python3 ccx_point.py {H} {out}'");
    }
    return s;
  }
  for (const auto& piece : splitTopLevel(text.substr(colon + 1), ';')) {
    if (!piece.empty()) {
      s.settings.push_back(splitAssignment(spec, line, piece));
    }
  }
  if (s.settings.empty()) {
    fail(spec, line, "series '" + s.name + "' sets no parameter");
  }
  return s;
}

} // namespace

std::string trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) {
    return {};
  }
  const auto last = text.find_last_not_of(" \t\r\n");
  return std::string(text.substr(first, last - first + 1));
}

std::vector<std::string> splitTopLevel(std::string_view text, char separator) {
  std::vector<std::string> out;
  std::string current;
  char quote = 0;
  int depth = 0;
  for (const char c : text) {
    if (quote != 0) {
      quote = c == quote ? 0 : quote;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '(' || c == '[' || c == '{') {
      ++depth;
    } else if ((c == ')' || c == ']' || c == '}') && depth > 0) {
      --depth;
    } else if (c == separator && depth == 0) {
      out.push_back(trim(current));
      current.clear();
      continue;
    }
    current += c;
  }
  out.push_back(trim(current));
  return out;
}

SweepSpec parseSweepFile(const std::string& text, const std::filesystem::path& file) {
  SweepSpec spec;
  spec.file = file;
  std::istringstream in(text);
  std::string raw;
  std::string section;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string content = trim(withoutComment(raw));
    if (content.empty()) {
      continue;
    }
    if (content.front() == '[') {
      if (content != "[vary]" && content != "[series]") {
        fail(spec, line, "unknown section '" + content + "' (sections: [vary], [series])");
      }
      section = content;
      continue;
    }
    if (section.empty()) {
      setKey(spec, line, splitAssignment(spec, line, content));
    } else if (section == "[vary]") {
      Parameter p = parseVary(spec, line, content);
      for (const auto& q : spec.vary) {
        if (q.name == p.name) {
          fail(spec, line, "parameter " + p.name + " is already varied at line " + std::to_string(q.line));
        }
      }
      spec.vary.push_back(std::move(p));
    } else {
      Series s = parseSeries(spec, line, content);
      for (const auto& t : spec.series) {
        if (t.name == s.name) {
          fail(spec, line, "series '" + s.name + "' is already defined at line " + std::to_string(t.line));
        }
      }
      spec.series.push_back(std::move(s));
    }
  }
  if (spec.study.empty()) {
    fail(spec, 0, "no 'study = <file>.export' line: the sweep needs the study it varies");
  }
  return spec;
}

void addVary(SweepSpec& spec, const std::string& option) {
  SweepSpec context;
  Parameter p = parseVary(context, 0, option);
  for (auto& q : spec.vary) {
    if (q.name == p.name) {
      q.values = p.values;
      return;
    }
  }
  spec.vary.push_back(std::move(p));
}

void validate(const SweepSpec& spec) {
  std::set<std::string> names;
  for (const auto& p : spec.vary) {
    names.insert(p.name);
  }
  for (const auto& s : spec.series) {
    for (const auto& [name, value] : s.settings) {
      if (names.count(name) != 0) {
        fail(spec, s.line, "series '" + s.name + "' sets " + name + ", which [vary] varies too");
      }
    }
  }
  if (!spec.meshCommand.empty() && spec.meshUnit == 0) {
    fail(spec, 0, "'mesh = ...' needs 'mesh_unit = N': the export's unit the generated mesh replaces");
  }
  if (!spec.meshCommand.empty() && spec.meshCommand.find("{mesh}") == std::string::npos) {
    fail(spec, 0,
         "the mesh command must write to {mesh}, e.g. 'gmsh ring.geo -2 -setnumber N {N} -o {mesh}'");
  }
  if (!spec.meshSize.empty() && names.count(spec.meshSize) == 0) {
    fail(spec, 0, "mesh_size names " + spec.meshSize + ", which is not a parameter of [vary]");
  }
  if (!spec.seriesParameter.empty() && names.count(spec.seriesParameter) == 0) {
    fail(spec, 0, "series names " + spec.seriesParameter + ", which is not a parameter of [vary]");
  }
  if (!spec.seriesParameter.empty() && !spec.series.empty()) {
    fail(spec, 0, "'series = NAME' and a [series] section: use one of them");
  }
}

} // namespace stella::sweep
