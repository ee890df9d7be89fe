#include "messages/Messages.hpp"

#include <fmt/args.h>

#include <map>
#include <sstream>

namespace stella::msg {

namespace {

struct KindInfo {
  Kind kind;
  const char* name;
};
constexpr KindInfo kinds[] = {{Kind::Info, "info"},
                              {Kind::Alarm, "alarm"},
                              {Kind::Fatal, "fatal"},
                              {Kind::Syntax, "syntax"},
                              {Kind::NoConvergence, "no-convergence"},
                              {Kind::Note, "note"}};

[[noreturn]] void malformed(std::string_view area, int line, const std::string& what) {
  throw InternalError(fmt::format("messages/{}.msg:{}: {}", area, line, what), __FILE__, __LINE__);
}

// `\n`, `\t` and `\\` in a .msg value.
std::string unescape(std::string_view v) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] == '\\' && i + 1 < v.size()) {
      const char c = v[++i];
      out += c == 'n' ? '\n' : c == 't' ? '\t' : c;
    } else {
      out += v[i];
    }
  }
  return out;
}

std::string escape(std::string_view v) {
  std::string out;
  for (char c : v) {
    out += c == '\n'   ? std::string("\\n")
           : c == '\t' ? std::string("\\t")
           : c == '\\' ? "\\\\"
                       : std::string(1, c);
  }
  return out;
}

std::string format(const Entry& e, const std::string& pattern, Args args) {
  fmt::dynamic_format_arg_store<fmt::format_context> store;
  for (const Arg& a : args) {
    std::visit([&](const auto& v) { store.push_back(fmt::arg(a.name(), v)); }, a.value());
  }
  try {
    return fmt::vformat(pattern, store);
  } catch (const fmt::format_error& err) {
    throw InternalError(fmt::format("message {} ({}.msg): {} in '{}'", e.key, e.area, err.what(), pattern),
                        __FILE__, __LINE__);
  }
}

const Entry& entry(std::string_view key) {
  const Entry* e = find(key);
  if (!e) {
    throw InternalError(fmt::format("message {} is not in the catalogue (messages/*.msg)", key), __FILE__,
                        __LINE__);
  }
  return *e;
}

} // namespace

const char* kindName(Kind k) {
  for (const KindInfo& i : kinds) {
    if (i.kind == k) {
      return i.name;
    }
  }
  return "fatal";
}

std::vector<Entry> parseMessageFile(std::string_view area, std::string_view text) {
  std::vector<Entry> entries;
  std::istringstream in{std::string(text)};
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') {
      continue;
    }
    if (line[0] == '[') {
      const auto close = line.find(']');
      if (close == std::string::npos || close + 1 >= line.size() || line[close + 1] != ' ') {
        malformed(area, number, "expected '[KEY] kind'");
      }
      Entry e;
      e.key = line.substr(1, close - 1);
      e.id = e.key.substr(0, e.key.find('.'));
      e.area = std::string(area);
      const std::string kind = line.substr(close + 2);
      bool known = false;
      for (const KindInfo& i : kinds) {
        if (kind == i.name) {
          e.kind = i.kind;
          known = true;
        }
      }
      if (!known) {
        malformed(area, number, "unknown kind '" + kind + "'");
      }
      entries.push_back(std::move(e));
    } else if (line.starts_with("text: ") && !entries.empty() && entries.back().text.empty()) {
      entries.back().text = unescape(std::string_view(line).substr(6));
    } else if (line.starts_with("note: ") && !entries.empty() && !entries.back().text.empty()) {
      entries.back().advice.push_back(unescape(std::string_view(line).substr(6)));
    } else {
      malformed(area, number, "expected '[KEY] kind', 'text: ...' or 'note: ...'");
    }
  }
  for (const Entry& e : entries) {
    if (e.text.empty()) {
      malformed(area, number, e.key + " has no text");
    }
  }
  return entries;
}

const std::vector<Entry>& catalogue() {
  static const std::vector<Entry> all = [] {
    std::vector<Entry> v;
    for (const MessageFile& f : embeddedMessageFiles()) {
      for (Entry& e : parseMessageFile(f.area, f.text)) {
        v.push_back(std::move(e));
      }
    }
    return v;
  }();
  return all;
}

const Entry* find(std::string_view key) {
  static const std::map<std::string, const Entry*, std::less<>> index = [] {
    std::map<std::string, const Entry*, std::less<>> m;
    for (const Entry& e : catalogue()) {
      if (!m.emplace(e.key, &e).second) {
        throw InternalError("message " + e.key + " is catalogued twice", __FILE__, __LINE__);
      }
    }
    return m;
  }();
  const auto it = index.find(key);
  return it == index.end() ? nullptr : it->second;
}

Diagnostic make(std::string_view key, Args args, SourceLocation at) {
  const Entry& e = entry(key);
  std::string message = format(e, e.text, args);
  Diagnostic d;
  switch (e.kind) {
  case Kind::Info:
    d = Diagnostic::info(e.id, std::move(message), std::move(at));
    break;
  case Kind::Alarm:
    d = Diagnostic::alarm(e.id, std::move(message), std::move(at));
    break;
  case Kind::Fatal:
    d = Diagnostic::fatal(e.id, std::move(message), std::move(at));
    break;
  case Kind::Syntax:
    d = Diagnostic::syntax(e.id, std::move(message), std::move(at));
    break;
  case Kind::NoConvergence:
    d = Diagnostic::noConvergence(e.id, std::move(message), std::move(at));
    break;
  case Kind::Note:
    throw InternalError("message " + e.key + " is a note: use msg::text", __FILE__, __LINE__);
  }
  for (const std::string& note : e.advice) {
    d.withNote(format(e, note, args));
  }
  return d;
}

std::string text(std::string_view key, Args args) {
  const Entry& e = entry(key);
  return format(e, e.text, args);
}

std::vector<std::string> placeholders(std::string_view pattern) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '{' && pattern[i] != '}') {
      continue;
    }
    if (i + 1 < pattern.size() && pattern[i + 1] == pattern[i]) {
      ++i; // {{ or }}
      continue;
    }
    if (pattern[i] == '}') {
      continue;
    }
    const auto end = pattern.find_first_of(":}", i + 1);
    if (end == std::string_view::npos) {
      break;
    }
    std::string name(pattern.substr(i + 1, end - i - 1));
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      names.push_back(std::move(name));
    }
    i = pattern.find('}', end);
  }
  return names;
}

std::string markdown() {
  std::ostringstream out;
  out << "# Messages\n\n"
         "<!-- Generated from messages/*.msg by `stella-messages doc`: do not edit. -->\n\n"
         "Every diagnostic stella prints has a message id (`CONTACT_1`, `MESH_2`...). This page lists\n"
         "them with their severity, their text and the advice printed under them as `note:` lines.\n"
         "`{name}` stands for a value computed by the run (a group name, a time, a count...). An id\n"
         "with several texts lists each of them. Severities: `<F>` fatal error, `<S>` exception (the\n"
         "results computed so far are kept, e.g. no convergence), `<A>` alarm, `<I>` information;\n"
         "`note` is an advice added only in some cases.\n";
  std::string area;
  for (const Entry& e : catalogue()) {
    if (e.area != area) {
      area = e.area;
      out << "\n## " << area << "\n\n| id | severity | text and advice |\n|---|---|---|\n";
    }
    const char* tag = e.kind == Kind::Note            ? "note"
                      : e.kind == Kind::Info          ? "`<I>`"
                      : e.kind == Kind::Alarm         ? "`<A>`"
                      : e.kind == Kind::NoConvergence ? "`<S>`"
                                                      : "`<F>`";
    auto cell = [](const std::string& s) {
      std::string r;
      for (char c : escape(s)) {
        r += c == '|' ? std::string("\\|") : std::string(1, c);
      }
      return r;
    };
    out << "| " << e.key << " | " << tag << " | " << cell(e.text);
    for (const std::string& a : e.advice) {
      out << "<br>note: " << cell(a);
    }
    out << " |\n";
  }
  return out.str();
}

} // namespace stella::msg
