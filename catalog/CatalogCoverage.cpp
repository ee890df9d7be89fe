// `tools/catalog-coverage`: runs command files through the interpreter without executing any
// operator, records every keyword path (COMMAND/FACTOR/KEYWORD) and every text value written,
// and reports the catalogue's keywords and allowed values that no file uses.
#include "Catalog.hpp"
#include "CommandSpec.hpp"

#include "interpreter/Interpreter.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace stella {

namespace {

struct Usage {
  std::set<std::string> keywords; // "CMD/FACT/KW"
  std::set<std::string> values;   // "CMD/FACT/KW=VALUE"
};

// Containers on the path being recorded: a list that contains itself (`a[0] = a`) is walked once,
// and nesting is bounded by the interpreter's own limit, so no input can exhaust the stack.
using Visiting = std::vector<const void*>;

void recordValue(const std::string& path, const Value& v, Usage& usage, Visiting& visiting);
void recordArguments(const std::string& path, const std::vector<KeywordArgument>& keywords, Usage& usage,
                     Visiting& visiting);

const void* containerIdentity(const Value& v) {
  if (v.isList()) {
    return v.asList().get();
  }
  if (v.isDict()) {
    return v.asDict().get();
  }
  if (v.isFactor()) {
    return v.asFactor().get();
  }
  return nullptr;
}

void recordContents(const std::string& path, const Value& v, Usage& usage, Visiting& visiting) {
  if (v.isSequence()) {
    for (const Value& x : v.items()) {
      recordValue(path, x, usage, visiting);
    }
  } else if (v.isFactor()) {
    recordArguments(path, v.asFactor()->keywords, usage, visiting);
  } else if (v.isDict()) {
    for (const auto& [key, value] : v.asDict()->items) {
      if (key.isString()) {
        usage.keywords.insert(path + "/" + key.asString());
        recordValue(path + "/" + key.asString(), value, usage, visiting);
      }
    }
  }
}

void recordValue(const std::string& path, const Value& v, Usage& usage, Visiting& visiting) {
  if (v.isString() || v.isInt()) {
    usage.values.insert(path + "=" + v.str());
    return;
  }
  if (!v.isSequence() && !v.isFactor() && !v.isDict()) {
    return;
  }
  const void* id = containerIdentity(v);
  const bool seen = id != nullptr && std::find(visiting.begin(), visiting.end(), id) != visiting.end();
  if (seen || visiting.size() >= static_cast<std::size_t>(maxValueNesting)) {
    return;
  }
  visiting.push_back(id);
  recordContents(path, v, usage, visiting);
  visiting.pop_back();
}

void recordArguments(const std::string& path, const std::vector<KeywordArgument>& keywords, Usage& usage,
                     Visiting& visiting) {
  for (const KeywordArgument& k : keywords) {
    usage.keywords.insert(path + "/" + k.name);
    if (k.value) {
      recordValue(path + "/" + k.name, *k.value, usage, visiting);
    }
  }
}

// Validates nothing and runs nothing: records the call and returns a concept of the type the
// catalogue would give, so that later calls see concepts where they expect them.
class RecordingHandler : public CommandHandler {
public:
  explicit RecordingHandler(Usage& usage) : usage_(usage) {}
  Value callCommand(const std::string& command, const CallArguments& args,
                    const std::string& target) override {
    Visiting visiting;
    recordArguments(command, args.keywords, usage_, visiting);
    usage_.keywords.insert(command);
    if (command == "FIN") {
      finished_ = true;
    }
    std::string type = "assd";
    try {
      type = Catalog::builtin().validate(command, args).resultType;
    } catch (const UserError&) {
    }
    if (target.empty() || type.empty()) {
      return Value();
    }
    auto c = std::make_shared<Concept>();
    c->name = target;
    c->type = type;
    return Value(c);
  }
  Value conceptAttribute(const std::shared_ptr<Concept>& concept_, const std::string& name,
                         const SourceLocation& at) override {
    throw UserError(msg::make("CATALOG_COV", {{"name", concept_->name}, {"name_2", name}}, at));
  }
  bool finished() const override { return finished_; }

private:
  Usage& usage_;
  bool finished_ = false;
};

class CountingSink : public DiagnosticSink {
public:
  int errors = 0;
  void report(const Diagnostic& d) override { errors += d.severity == Severity::Fatal ? 1 : 0; }
};

void walk(const Level& level, const std::string& path, const Usage& usage,
          std::vector<std::string>& unusedKeywords, std::vector<std::string>& unusedValues, int& keywordCount,
          int& valueCount) {
  for (const Entry& e : level.entries) {
    if (e.block) {
      walk(e.block->body, path, usage, unusedKeywords, unusedValues, keywordCount, valueCount);
      continue;
    }
    std::string p = path + "/" + e.name;
    ++keywordCount;
    if (!usage.keywords.count(p)) {
      unusedKeywords.push_back(p);
    }
    if (e.factor) {
      walk(e.factor->body, p, usage, unusedKeywords, unusedValues, keywordCount, valueCount);
    } else if (e.simple) {
      for (const Value& v : e.simple->into) {
        if (!v.isString()) {
          continue;
        }
        ++valueCount;
        if (!usage.values.count(p + "=" + v.str())) {
          unusedValues.push_back(p + "=" + v.str());
        }
      }
    }
  }
}

} // namespace

std::string catalogCoverage(const std::vector<std::filesystem::path>& commandFiles) {
  Usage usage;
  std::string failures;
  for (const auto& path : commandFiles) {
    RecordingHandler handler(usage);
    CountingSink sink;
    Interpreter interp(handler, sink);
    for (const auto& name : Catalog::builtin().commandNames()) {
      interp.defineCommand(name);
    }
    try {
      RunStatus status = interp.run(SourceFile::load(path.string()));
      if (status == RunStatus::SyntaxError || status == RunStatus::Failed) {
        failures += "- " + path.string() + ": stopped early (" + std::to_string(sink.errors) +
                    " error(s)); the rest is not counted\n";
      }
    } catch (const UserError& e) {
      failures += "- " + path.string() + ": " + e.first().message + "\n";
    }
  }
  const Catalog& catalog = Catalog::builtin();
  std::string out =
      "# Catalogue coverage\n\n" + std::to_string(commandFiles.size()) + " command file(s) read.\n\n";
  if (!failures.empty()) {
    out += "## Files not fully read\n\n" + failures + "\n";
  }
  std::string details;
  int totalKeywords = 0;
  int totalValues = 0;
  int unusedKeywordsTotal = 0;
  int unusedValuesTotal = 0;
  std::string table = "| Command | keywords unused | values unused |\n|---|---|---|\n";
  for (const auto& name : catalog.commandNames()) {
    std::vector<std::string> unusedKeywords;
    std::vector<std::string> unusedValues;
    int keywordCount = 0;
    int valueCount = 0;
    walk(catalog.find(name)->body, name, usage, unusedKeywords, unusedValues, keywordCount, valueCount);
    totalKeywords += keywordCount;
    totalValues += valueCount;
    unusedKeywordsTotal += static_cast<int>(unusedKeywords.size());
    unusedValuesTotal += static_cast<int>(unusedValues.size());
    table += "| " + name + (usage.keywords.count(name) ? "" : " (never called)") + " | " +
             std::to_string(unusedKeywords.size()) + "/" + std::to_string(keywordCount) + " | " +
             std::to_string(unusedValues.size()) + "/" + std::to_string(valueCount) + " |\n";
    if (!unusedKeywords.empty() || !unusedValues.empty()) {
      details += "### " + name + "\n\n";
      if (!unusedKeywords.empty()) {
        details += "Keywords never written:";
        for (const auto& k : unusedKeywords) {
          details += " " + k.substr(name.size() + 1);
        }
        details += "\n\n";
      }
      if (!unusedValues.empty()) {
        details += "Allowed values never written:";
        for (const auto& v : unusedValues) {
          details += " " + v.substr(name.size() + 1);
        }
        details += "\n\n";
      }
    }
  }
  out += "Keywords used: " + std::to_string(totalKeywords - unusedKeywordsTotal) + " of " +
         std::to_string(totalKeywords) +
         "; allowed text values used: " + std::to_string(totalValues - unusedValuesTotal) + " of " +
         std::to_string(totalValues) +
         " (a keyword counts once per place in the tree; blocks are transparent).\n\n";
  out += table + "\n## Unused keywords and values\n\n" + details;
  return out;
}

} // namespace stella
