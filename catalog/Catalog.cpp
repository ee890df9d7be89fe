// The built-in catalogue: loads the embedded catalogue files once, checks them, and offers
// validation, the human-readable tree of a command and the JSON export (Catalog.hpp).
#include "Catalog.hpp"

#include "CatalogLoader.hpp"
#include "CatalogText.hpp"
#include "CommandSpec.hpp"
#include "Validator.hpp"
#include "interpreter/StringEscape.hpp"
#include "messages/Messages.hpp"

#include <fmt/format.h>

namespace stella {

struct Catalog::Impl {
  LoadedCatalog loaded;
};

Catalog::Catalog() : impl_(std::make_unique<Impl>()) {}
Catalog::~Catalog() = default;
Catalog::Catalog(Catalog&&) noexcept = default;

const Catalog& Catalog::builtin() {
  static const Catalog catalog = [] {
    Catalog c;
    c.impl_->loaded = loadCatalog(embeddedCatalogFiles());
    std::vector<std::string> problems = checkCatalog(c.impl_->loaded);
    if (!problems.empty()) {
      std::string message = "the built-in catalogue is broken:";
      for (const auto& p : problems) {
        message += "\n  " + p;
      }
      throw InternalError(message, __FILE__, __LINE__);
    }
    return c;
  }();
  return catalog;
}

Catalog Catalog::fromFiles(const std::vector<std::pair<std::string, std::string>>& files) {
  std::vector<CatalogFile> list;
  for (const auto& [path, text] : files) {
    list.push_back(CatalogFile{path, text});
  }
  Catalog c;
  c.impl_->loaded = loadCatalog(list);
  return c;
}

std::vector<std::string> Catalog::problems() const {
  return checkCatalog(impl_->loaded);
}

std::vector<std::string> Catalog::commandNames() const {
  std::vector<std::string> names;
  for (const auto& [name, spec] : impl_->loaded.commands) {
    names.push_back(name);
  }
  return names;
}

const CommandSpec* Catalog::find(const std::string& command) const {
  auto it = impl_->loaded.commands.find(command);
  return it == impl_->loaded.commands.end() ? nullptr : it->second.get();
}

const ConceptTypes& Catalog::conceptTypes() const {
  return impl_->loaded.types;
}

ValidatedCall Catalog::validate(const std::string& command, const CallArguments& args) const {
  const CommandSpec* spec = find(command);
  if (spec == nullptr) {
    std::vector<std::string> notes;
    std::string best;
    std::size_t bestDistance = 3;
    for (const auto& [name, s] : impl_->loaded.commands) {
      std::size_t d = editDistance(name, command);
      if (d < bestDistance) {
        bestDistance = d;
        best = name;
      }
    }
    Diagnostic d = msg::make("CATALOG_12", {{"command", command}}, args.callLocation);
    if (!best.empty()) {
      d.withNote(msg::text("CATALOG_12.n1", {{"best", best}}));
    }
    throw UserError(std::move(d));
  }
  return validateCall(*spec, impl_->loaded.types, args);
}

namespace {

std::string bounds(int min, int max) {
  if (min == 1 && max == 1) {
    return "";
  }
  return fmt::format(" [{}..{}]", min, max == kUnbounded ? std::string("**") : std::to_string(max));
}

std::string values(const ValueList& list) {
  std::string out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    out += (i ? ", " : "") + list[i].repr();
  }
  return out;
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    out += (i ? sep : "") + v[i];
  }
  return out;
}

void describeLevel(const Level& level, int indent, std::string& out);

void describeRules(const Level& level, int indent, std::string& out) {
  for (const Rule& r : level.rules) {
    out += std::string(static_cast<std::size_t>(indent), ' ') + "rule " + r.text() + "\n";
  }
  if (!level.outOfScope.empty()) {
    out += std::string(static_cast<std::size_t>(indent), ' ') +
           "outside stella's scope: " + join(level.outOfScope, ", ") + "\n";
  }
}

void describeLevel(const Level& level, int indent, std::string& out) {
  std::string pad(static_cast<std::size_t>(indent), ' ');
  describeRules(level, indent, out);
  for (const Entry& e : level.entries) {
    if (e.simple) {
      const SimpleSpec& s = *e.simple;
      out += pad + e.name + " : " + join(s.types, "|") + " " + presenceLetter(s.presence);
      if (s.defaultValue) {
        out += " default=" + (s.defaultValue->size() == 1 ? s.defaultValue->front().repr()
                                                          : "(" + values(*s.defaultValue) + ")");
      }
      if (!s.into.empty()) {
        out += " into=(" + values(s.into) + ")";
      }
      out += bounds(s.min, s.max);
      if (s.valMin) {
        out += " >=" + Value(*s.valMin).repr();
      }
      if (s.valMax) {
        out += " <=" + Value(*s.valMax).repr();
      }
      if (s.noRepeat) {
        out += " no-repeat";
      }
      if (!s.outOfScopeValues.empty()) {
        out += " (outside stella's scope: " + values(s.outOfScopeValues) + ")";
      }
      if (!s.renamedTo.empty()) {
        out += " (old spelling of " + s.renamedTo + ")";
      }
      if (s.notImplemented) {
        out += s.acceptedValue ? " (not implemented yet, except " + s.acceptedValue->repr() + ")"
                               : std::string(" (not implemented yet)");
      }
      if (!s.implementedValues.empty()) {
        out += " (implemented: " + values(s.implementedValues) + ")";
      }
      out += "  -- " + s.description + "\n";
    } else if (e.factor) {
      const FactorSpec& f = *e.factor;
      out += pad + e.name + " : FACT " + presenceLetter(f.presence) + bounds(f.min, f.max);
      if (!f.renamedTo.empty()) {
        out += " (old spelling of " + f.renamedTo + ")";
      }
      if (f.notImplemented) {
        out += " (not implemented yet)";
      }
      out += "  -- " + f.description + "\n";
      describeLevel(f.body, indent + 4, out);
    } else if (e.block) {
      out += pad + "BLOC " + e.name + " if " + e.block->conditionText + "\n";
      describeLevel(e.block->body, indent + 4, out);
    }
  }
}

std::string jsonString(const std::string& s) {
  return quoted(s, '"', EscapeStyle::Json);
}

std::string jsonValue(const Value& v) {
  if (v.isString()) {
    return jsonString(v.asString());
  }
  if (v.isInt()) {
    return std::to_string(v.asInt());
  }
  if (v.isReal()) {
    std::string text = fmt::format("{}", v.asReal()); // shortest round-trip form
    if (text.find_first_of(".eEn") == std::string::npos) {
      text += ".0"; // keep reals recognisable as reals (100.0, not 100)
    }
    return text;
  }
  if (v.isBool()) {
    return v.asBool() ? "true" : "false";
  }
  return jsonString(v.repr());
}

std::string jsonValues(const ValueList& list) {
  std::string out = "[";
  for (std::size_t i = 0; i < list.size(); ++i) {
    out += (i ? "," : "") + jsonValue(list[i]);
  }
  return out + "]";
}

std::string jsonLevel(const Level& level);

std::string jsonStrings(const std::vector<std::string>& list) {
  std::string out = "[";
  for (std::size_t i = 0; i < list.size(); ++i) {
    out += (i ? "," : "") + jsonString(list[i]);
  }
  return out + "]";
}

std::string jsonLevel(const Level& level) {
  std::string out = "\"rules\":[";
  for (std::size_t i = 0; i < level.rules.size(); ++i) {
    const Rule& r = level.rules[i];
    out += (i ? "," : "") + std::string("{\"kind\":") + jsonString(r.keyword()) +
           ",\"keywords\":" + jsonStrings(r.names) + ",\"defaults\":{";
    for (std::size_t j = 0; j < r.defaults.size(); ++j) {
      out += (j ? "," : "") + jsonString(r.defaults[j].first) + ":" + jsonValue(r.defaults[j].second);
    }
    out += "}}";
  }
  out += "],\"out_of_scope\":" + jsonStrings(level.outOfScope) + ",\"entries\":[";
  for (std::size_t i = 0; i < level.entries.size(); ++i) {
    const Entry& e = level.entries[i];
    out += i ? "," : "";
    if (e.simple) {
      const SimpleSpec& s = *e.simple;
      out += "{\"kind\":\"SIMP\",\"name\":" + jsonString(e.name) + ",\"statut\":\"" +
             presenceLetter(s.presence) + "\",\"typ\":" + jsonStrings(s.types) +
             ",\"min\":" + std::to_string(s.min) +
             ",\"max\":" + (s.max == kUnbounded ? std::string("\"**\"") : std::to_string(s.max));
      if (s.defaultValue) {
        out += ",\"default\":" + jsonValues(*s.defaultValue);
      }
      if (!s.into.empty()) {
        out += ",\"into\":" + jsonValues(s.into);
      }
      if (s.valMin) {
        out += ",\"val_min\":" + jsonValue(Value(*s.valMin));
      }
      if (s.valMax) {
        out += ",\"val_max\":" + jsonValue(Value(*s.valMax));
      }
      if (!s.renamedTo.empty()) {
        out += ",\"replaced_by\":" + jsonString(s.renamedTo);
      }
      out += ",\"description\":" + jsonString(s.description) + "}";
    } else if (e.factor) {
      const FactorSpec& f = *e.factor;
      out += "{\"kind\":\"FACT\",\"name\":" + jsonString(e.name) + ",\"statut\":\"" +
             presenceLetter(f.presence) + "\",\"min\":" + std::to_string(f.min) +
             ",\"max\":" + (f.max == kUnbounded ? std::string("\"**\"") : std::to_string(f.max)) +
             ",\"description\":" + jsonString(f.description) +
             (f.renamedTo.empty() ? "" : ",\"replaced_by\":" + jsonString(f.renamedTo)) + "," +
             jsonLevel(f.body) + "}";
    } else if (e.block) {
      out += "{\"kind\":\"BLOC\",\"name\":" + jsonString(e.name) +
             ",\"condition\":" + jsonString(e.block->conditionText) + "," + jsonLevel(e.block->body) + "}";
    }
  }
  return out + "]";
}

} // namespace

const char* commandKindName(CommandKind k) {
  return k == CommandKind::Oper ? "OPER" : k == CommandKind::Macro ? "MACRO" : "PROC";
}

std::string describeResult(const CommandSpec& c) {
  if (!c.resultFrom.empty()) {
    return "the type of the concept given to " + join(c.resultFrom, " or ");
  }
  std::string out;
  for (const auto& [condition, type] : c.resultCases) {
    out += (out.empty() ? "" : "; ") + type + " if " + condition->text();
  }
  if (!c.resultType.empty()) {
    out += (out.empty() ? "" : "; otherwise ") + c.resultType;
  }
  return out.empty() ? "nothing" : out;
}

std::string describeReuse(const CommandSpec& c) {
  switch (c.reentrant) {
  case 'o':
    return "must reuse" +
           (c.reuseKeyword.empty() ? "" : " (reuse= the concept given to " + c.reuseKeyword + ")");
  case 'f':
    return "may reuse" +
           (c.reuseKeyword.empty() ? "" : " (reuse= the concept given to " + c.reuseKeyword + ")");
  default:
    return "never reuses";
  }
}

std::string Catalog::describe(const std::string& command) const {
  const CommandSpec* c = find(command);
  if (c == nullptr) {
    throw UserError(msg::make("CATALOG_12.2", {{"command", command}}));
  }
  std::string out = c->name + " = " + commandKindName(c->kind) + "  -- " + c->description + "\n";
  out += "  returns: " + describeResult(*c) + "; " + describeReuse(*c) + "\n";
  describeLevel(c->body, 2, out);
  return out;
}

std::string Catalog::toJson() const {
  std::string out = "{\"commands\":[";
  bool first = true;
  for (const auto& [name, c] : impl_->loaded.commands) {
    out += first ? "" : ",";
    first = false;
    out += "{\"name\":" + jsonString(name) + ",\"kind\":\"" + commandKindName(c->kind) +
           "\",\"description\":" + jsonString(c->description) +
           ",\"result\":" + jsonString(describeResult(*c)) + ",\"reentrant\":\"" +
           std::string(1, c->reentrant) + "\",\"reuse_keyword\":" + jsonString(c->reuseKeyword) + "," +
           jsonLevel(c->body) + "}";
  }
  return out + "]}\n";
}

} // namespace stella
