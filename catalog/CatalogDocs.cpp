// The reference pages of doc/catalog/, generated from the catalogue: one Markdown page per
// command (keyword tree with types, statut, defaults, allowed values, bounds, rules, blocks and
// descriptions) and an index. Deterministic, so that CI can diff them against the repository.
#include "Catalog.hpp"
#include "CatalogText.hpp"
#include "CommandSpec.hpp"
#include "messages/Messages.hpp"

#include <fmt/format.h>

#include <fstream>

namespace stella {

namespace {

std::string valueList(const ValueList& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += (i ? ", " : "") + std::string("`") + values[i].repr() + "`";
  }
  return out;
}

std::string presenceWord(Presence p) {
  switch (p) {
  case Presence::Mandatory:
    return "mandatory";
  case Presence::Optional:
    return "optional";
  case Presence::Hidden:
    return "hidden";
  case Presence::Defaulted:
    return "created with its defaults when absent";
  }
  return "";
}

std::string count(int min, int max, const char* what) {
  if (min == 1 && max == 1) {
    return "";
  }
  return fmt::format(", {} {}..{}", what, min, max == kUnbounded ? std::string("**") : std::to_string(max));
}

std::string join(const std::vector<std::string>& v, const std::string& sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    out += (i ? sep : "") + v[i];
  }
  return out;
}

// What stella implements of a keyword (non_implemente=, accepte=, implemente=, stella=).
void writeSupport(const SimpleSpec& s, const std::string& pad, std::string& out) {
  if (s.notImplemented) {
    out += pad + "  - **not implemented yet** in stella" +
           (s.notImplemented->empty() ? "" : ": " + *s.notImplemented);
    if (s.acceptedValue) {
      out += " (" + s.acceptedValue->repr() + " accepted)";
    }
    out += "\n";
  }
  if (!s.implementedValues.empty()) {
    out += pad + "  - implemented in stella: " + valueList(s.implementedValues) +
           " (the others: not implemented yet)\n";
  }
  if (!s.stellaNote.empty()) {
    out += pad + "  - in stella: " + s.stellaNote + "\n";
  }
}

void writeLevel(const Level& level, int depth, std::string& out) {
  std::string pad(static_cast<std::size_t>(2 * depth), ' ');
  for (const Rule& r : level.rules) {
    out += pad + "- rule `" + r.text() + "`: " + r.explanation() + "\n";
  }
  if (!level.outOfScope.empty()) {
    out += pad + "- outside stella's scope (refused by name): " + join(level.outOfScope, ", ") + "\n";
  }
  for (const Entry& e : level.entries) {
    if (e.simple) {
      const SimpleSpec& s = *e.simple;
      std::vector<std::string> types;
      for (const auto& t : s.types) {
        types.push_back("`" + t + "`");
      }
      out += pad + "- **" + e.name + "** (" + join(types, " or ") + ", " + presenceWord(s.presence) +
             count(s.min, s.max, "values");
      if (s.defaultValue) {
        out += ", default " + valueList(*s.defaultValue);
      }
      if (s.valMin) {
        out += ", ≥ " + Value(*s.valMin).repr();
      }
      if (s.valMax) {
        out += ", ≤ " + Value(*s.valMax).repr();
      }
      if (s.noRepeat) {
        out += ", no repeated value";
      }
      out += ") — " + s.description + "\n";
      if (!s.into.empty()) {
        out += pad + "  - allowed: " + valueList(s.into) + "\n";
      }
      if (!s.outOfScopeValues.empty()) {
        out += pad + "  - outside stella's scope: " + valueList(s.outOfScopeValues) + "\n";
      }
      if (!s.renamedTo.empty()) {
        out += pad + "  - older spelling, read as **" + s.renamedTo + "**\n";
      }
      writeSupport(s, pad, out);
      if (s.oldFactorForm) {
        out += pad + "  - 2020 form `" + e.name + "=_F(...)` accepted and read as " +
               (s.oldFactorValue ? s.oldFactorValue->repr() : std::string("'OUI'")) + ":\n";
        writeLevel(s.oldFactorForm->body, depth + 2, out);
      }
    } else if (e.factor) {
      const FactorSpec& f = *e.factor;
      out += pad + "- **" + e.name + "** (factor keyword, " + presenceWord(f.presence) +
             count(f.min, f.max, "occurrences") + ") — " + f.description + "\n";
      if (!f.renamedTo.empty()) {
        out += pad + "  - older spelling, read as **" + f.renamedTo + "**\n";
      }
      if (f.notImplemented) {
        out += pad + "  - **not implemented yet** in stella" +
               (f.notImplemented->empty() ? "" : ": " + *f.notImplemented) + "\n";
      }
      if (!f.stellaNote.empty()) {
        out += pad + "  - in stella: " + f.stellaNote + "\n";
      }
      writeLevel(f.body, depth + 1, out);
    } else if (e.block) {
      out += pad + "- *when* `" + e.block->conditionText + "`:\n";
      writeLevel(e.block->body, depth + 1, out);
    }
  }
}

std::string page(const CommandSpec& c) {
  std::string out = "# " + c.name + "\n\n" + c.description + "\n\n";
  out += std::string("- kind: ") + commandKindName(c.kind) + "\n";
  out += "- returns: " + describeResult(c) + "\n";
  out += "- reuse: " + describeReuse(c) + "\n";
  out += "- catalogue file: `" + c.file + "`\n";
  if (c.notImplemented) {
    out += "- **not implemented yet** in stella (the catalogue validates it; a run refuses it)" +
           (c.notImplemented->empty() ? "" : ": " + *c.notImplemented) + "\n";
  }
  out += "\n";
  out += "## Keywords\n\n";
  writeLevel(c.body, 0, out);
  return out;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  if (!f || !(f << text)) {
    throw UserError(msg::make("CATALOG_DOC", {{"path", path.string()}}));
  }
}

} // namespace

void writeCatalogDocs(const std::filesystem::path& dir) {
  const Catalog& catalog = Catalog::builtin();
  std::filesystem::create_directories(dir);
  std::string index =
      "# Command catalogue\n\n"
      "Generated from `catalog/commands/` by `stella-catalog docs doc/catalog` (do not edit by hand).\n"
      "Each page lists a command's keywords with their type, statut, defaults, allowed values,\n"
      "conditional blocks and rules.\n\n"
      "| Command | Kind | Returns | Description |\n|---|---|---|---|\n";
  for (const auto& name : catalog.commandNames()) {
    const CommandSpec& c = *catalog.find(name);
    index += "| [" + name + "](" + name + ".md) | " + commandKindName(c.kind) + " | " + describeResult(c) +
             " | " + c.description + " |\n";
    writeFile(dir / (name + ".md"), page(c));
  }
  writeFile(dir / "README.md", index);
}

} // namespace stella
