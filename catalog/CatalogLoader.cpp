// Builds the catalogue model by running the catalogue files with the Interpreter (see
// CatalogLoader.hpp): each building block (SIMP, FACT, BLOC, OPER, rules...) is a native
// function whose keyword arguments are either attributes (statut, typ, defaut...) or, when the
// value is itself a building block, a child keyword named by the argument.
#include "CatalogLoader.hpp"

#include "interpreter/Diagnostics.hpp"
#include "interpreter/Interpreter.hpp"
#include "messages/Messages.hpp"

#include <algorithm>

namespace stella {

namespace {

// The value a building block returns to the catalogue file.
class SpecObject : public NativeObject {
public:
  std::shared_ptr<SimpleSpec> simple;
  std::shared_ptr<FactorSpec> factor;
  std::shared_ptr<BlockSpec> block;
  std::shared_ptr<CommandSpec> command;
  std::optional<Rule> rule;
  bool noRepeat = false;
  std::string typeName() const override {
    return simple    ? "SIMP"
           : factor  ? "FACT"
           : block   ? "BLOC"
           : command ? "command entry"
           : rule    ? "rule"
                     : "validator";
  }
};

// An error in a .cata file: catalogue entry `key` (messages/catalog.msg) formatted with `args`.
[[noreturn]] void fail(std::string_view key, msg::Args args = {}) {
  throw UserError(msg::make(key, args));
}

const SpecObject* specOf(const Value& v) {
  return v.isNative() ? dynamic_cast<const SpecObject*>(v.asNative().get()) : nullptr;
}

std::string text(const KeywordArgument& k) {
  if (!k.value->isString()) {
    fail("CATALOG_DEF.3", {{"name", k.name}, {"repr", k.value->repr()}});
  }
  return k.value->asString();
}

ValueList listOf(const Value& v) {
  return v.isSequence() ? v.items() : ValueList{v};
}

std::vector<std::string> texts(const KeywordArgument& k) {
  std::vector<std::string> out;
  for (const Value& v : listOf(*k.value)) {
    if (!v.isString()) {
      fail("CATALOG_DEF.4", {{"name", k.name}, {"repr", v.repr()}});
    }
    out.push_back(v.asString());
  }
  return out;
}

int bound(const KeywordArgument& k) {
  if (k.value->isString() && k.value->asString() == "**") {
    return kUnbounded;
  }
  if (!k.value->isInt()) {
    fail("CATALOG_DEF.5", {{"name", k.name}, {"repr", k.value->repr()}});
  }
  return static_cast<int>(k.value->asInt());
}

Presence presence(const KeywordArgument& k) {
  std::string s = text(k);
  if (s == "o") {
    return Presence::Mandatory;
  }
  if (s == "f") {
    return Presence::Optional;
  }
  if (s == "c") {
    return Presence::Hidden;
  }
  if (s == "d") {
    return Presence::Defaulted;
  }
  fail("CATALOG_DEF.6", {{"s", s}});
}

// Adds a child keyword or block to a level; returns false when the argument is an attribute.
bool addChild(Level& level, const KeywordArgument& k) {
  const SpecObject* s = specOf(*k.value);
  if (s == nullptr || !(s->simple || s->factor || s->block)) {
    return false;
  }
  for (const Entry& e : level.entries) {
    if (e.name == k.name) {
      fail("CATALOG_DEF.7", {{"name", k.name}});
    }
  }
  level.entries.push_back(Entry{k.name, s->simple, s->factor, s->block});
  return true;
}

// Attributes shared by levels: regles, hors_perimetre.
bool levelAttribute(Level& level, const KeywordArgument& k) {
  if (k.name == "regles") {
    for (const Value& v : listOf(*k.value)) {
      const SpecObject* s = specOf(v);
      if (s == nullptr || !s->rule) {
        fail("CATALOG_DEF.8", {{"repr", v.repr()}});
      }
      level.rules.push_back(*s->rule);
    }
    return true;
  }
  if (k.name == "hors_perimetre") {
    level.outOfScope = texts(k);
    return true;
  }
  return false;
}

Value wrap(std::shared_ptr<SpecObject> s) {
  return Value(std::shared_ptr<NativeObject>(std::move(s)));
}

void noPositional(const CallArguments& a, const char* what) {
  if (!a.positional.empty()) {
    fail("CATALOG_DEF.9", {{"what", std::string(what)}});
  }
}

Value makeSimple(const CallArguments& a) {
  noPositional(a, "SIMP");
  auto s = std::make_shared<SimpleSpec>();
  for (const KeywordArgument& k : a.keywords) {
    const Value& v = *k.value;
    if (k.name == "statut") {
      s->presence = presence(k);
    } else if (k.name == "typ") {
      s->types = texts(k);
    } else if (k.name == "defaut") {
      s->defaultValue = listOf(v);
    } else if (k.name == "into") {
      s->into = listOf(v);
    } else if (k.name == "hors_perimetre") {
      s->outOfScopeValues = listOf(v);
    } else if (k.name == "non_implemente") {
      s->notImplemented = text(k);
    } else if (k.name == "accepte") {
      s->acceptedValue = v;
    } else if (k.name == "implemente") {
      s->implementedValues = listOf(v);
    } else if (k.name == "stella") {
      s->stellaNote = text(k);
    } else if (k.name == "min") {
      s->min = bound(k);
    } else if (k.name == "max") {
      s->max = bound(k);
    } else if (k.name == "val_min" || k.name == "val_max") {
      if (!v.isNumber()) {
        fail("CATALOG_DEF.10", {{"name", k.name}, {"repr", v.repr()}});
      }
      (k.name == "val_min" ? s->valMin : s->valMax) = v.asReal();
    } else if (k.name == "validators") {
      const SpecObject* o = specOf(v);
      s->noRepeat = o != nullptr && o->noRepeat;
    } else if (k.name == "fr") {
      s->description = text(k);
    } else if (k.name == "remplace_par") {
      s->renamedTo = text(k);
    } else if (k.name == "forme_2020") {
      const SpecObject* o = specOf(v);
      if (o == nullptr || !o->factor) {
        fail("CATALOG_DEF.11", {});
      }
      s->oldFactorForm = o->factor;
    } else if (k.name == "valeur_2020") {
      s->oldFactorValue = v;
    } else {
      fail("CATALOG_DEF.12", {{"name", k.name}});
    }
  }
  if (s->types.empty()) {
    fail("CATALOG_DEF.13", {});
  }
  if (s->acceptedValue && !s->notImplemented) {
    fail("CATALOG_DEF.14", {});
  }
  for (const Value& v : s->implementedValues) {
    if (std::none_of(s->into.begin(), s->into.end(), [&](const Value& x) { return x.equals(v); })) {
      fail("CATALOG_DEF.15", {{"repr", v.repr()}});
    }
  }
  auto o = std::make_shared<SpecObject>();
  o->simple = std::move(s);
  return wrap(std::move(o));
}

Value makeFactor(const CallArguments& a) {
  noPositional(a, "FACT");
  auto f = std::make_shared<FactorSpec>();
  for (const KeywordArgument& k : a.keywords) {
    if (addChild(f->body, k) || levelAttribute(f->body, k)) {
      continue;
    }
    if (k.name == "statut") {
      f->presence = presence(k);
    } else if (k.name == "min") {
      f->min = bound(k);
    } else if (k.name == "max") {
      f->max = bound(k);
    } else if (k.name == "fr") {
      f->description = text(k);
    } else if (k.name == "remplace_par") {
      f->renamedTo = text(k);
    } else if (k.name == "non_implemente") {
      f->notImplemented = text(k);
    } else if (k.name == "stella") {
      f->stellaNote = text(k);
    } else {
      fail("CATALOG_DEF.16", {{"name", k.name}});
    }
  }
  auto o = std::make_shared<SpecObject>();
  o->factor = std::move(f);
  return wrap(std::move(o));
}

Value makeBlock(const CallArguments& a) {
  noPositional(a, "BLOC");
  auto b = std::make_shared<BlockSpec>();
  for (const KeywordArgument& k : a.keywords) {
    if (addChild(b->body, k) || levelAttribute(b->body, k)) {
      continue;
    }
    if (k.name == "condition") {
      b->conditionText = text(k);
      b->condition = std::make_shared<const CompiledExpression>(
          CompiledExpression::compile(b->conditionText, k.valueLocation));
    } else if (k.name == "fr") {
      b->description = text(k);
    } else {
      fail("CATALOG_DEF.17", {{"name", k.name}});
    }
  }
  if (!b->condition) {
    fail("CATALOG_DEF.18", {});
  }
  auto o = std::make_shared<SpecObject>();
  o->block = std::move(b);
  return wrap(std::move(o));
}

NativeFunction makeCommand(CommandKind kind) {
  return [kind](const CallArguments& a) -> Value {
    noPositional(a, "OPER");
    auto c = std::make_shared<CommandSpec>();
    c->kind = kind;
    for (const KeywordArgument& k : a.keywords) {
      if (addChild(c->body, k) || levelAttribute(c->body, k)) {
        continue;
      }
      const Value& v = *k.value;
      if (k.name == "fr") {
        c->description = text(k);
      } else if (k.name == "result") {
        if (v.isString()) {
          c->resultType = v.asString();
        } else if (v.isDict()) {
          for (const auto& [cond, type] : v.asDict()->items) {
            if (!cond.isString() || !type.isString()) {
              fail("CATALOG_DEF.19", {});
            }
            c->resultCases.emplace_back(
                std::make_shared<const CompiledExpression>(CompiledExpression::compile(cond.asString())),
                type.asString());
          }
        } else {
          fail("CATALOG_DEF.20", {});
        }
      } else if (k.name == "result_from") {
        c->resultFrom = texts(k);
      } else if (k.name == "mots_cles_libres") {
        c->body.freeKeywords = v.truthy();
      } else if (k.name == "reentrant") {
        std::string r = text(k);
        if (r.empty() || (r[0] != 'n' && r[0] != 'o' && r[0] != 'f')) {
          fail("CATALOG_DEF.21", {});
        }
        c->reentrant = r[0];
        if (r.size() > 2 && r[1] == ':') {
          c->reuseKeyword = r.substr(2);
        }
      } else if (k.name == "supprimes") {
        c->removedKeywords = texts(k);
      } else if (k.name == "non_implemente") {
        c->notImplemented = text(k);
      } else {
        fail("CATALOG_DEF.22", {{"name", k.name}});
      }
    }
    if (kind == CommandKind::Proc && (!c->resultType.empty() || !c->resultCases.empty())) {
      fail("CATALOG_DEF.23", {});
    }
    auto o = std::make_shared<SpecObject>();
    o->command = std::move(c);
    return wrap(std::move(o));
  };
}

NativeFunction makeRule(Rule::Kind kind) {
  return [kind](const CallArguments& a) -> Value {
    Rule r;
    r.kind = kind;
    for (const Value& v : a.positional) {
      if (!v.isString()) {
        fail("CATALOG_DEF.24", {{"repr", v.repr()}});
      }
      r.names.push_back(v.asString());
    }
    for (const KeywordArgument& k : a.keywords) {
      if (kind != Rule::Kind::UnParmi && kind != Rule::Kind::AuMoinsUn) {
        fail("CATALOG_DEF.25", {});
      }
      r.defaults.emplace_back(k.name, *k.value);
    }
    auto o = std::make_shared<SpecObject>();
    o->rule = std::move(r);
    return wrap(std::move(o));
  };
}

class CollectingSink : public DiagnosticSink {
public:
  std::vector<Diagnostic> errors;
  void report(const Diagnostic& d) override {
    if (d.severity == Severity::Fatal || d.severity == Severity::Exception) {
      errors.push_back(d);
    }
  }
};

class NoCommands : public CommandHandler {
public:
  Value callCommand(const std::string& command, const CallArguments&, const std::string&) override {
    throw UserError(msg::make("CATALOG_DEF", {{"command", command}}));
  }
  Value conceptAttribute(const std::shared_ptr<Concept>&, const std::string& name,
                         const SourceLocation& at) override {
    throw UserError(msg::make("CATALOG_DEF.2", {{"name", name}}, at));
  }
  bool finished() const override { return false; }
};

std::string stem(const std::string& path) {
  std::string base = path.substr(path.find_last_of('/') + 1);
  return base.substr(0, base.find('.'));
}

} // namespace

LoadedCatalog loadCatalog(const std::vector<CatalogFile>& files) {
  LoadedCatalog out;
  std::map<std::string, std::string> glossary;
  CollectingSink sink;
  NoCommands handler;
  Interpreter interp(handler, sink);
  interp.defineNative("SIMP", makeSimple);
  interp.defineNative("FACT", makeFactor);
  interp.defineNative("BLOC", makeBlock);
  interp.defineNative("OPER", makeCommand(CommandKind::Oper));
  interp.defineNative("MACRO", makeCommand(CommandKind::Macro));
  interp.defineNative("PROC", makeCommand(CommandKind::Proc));
  interp.defineNative("UN_PARMI", makeRule(Rule::Kind::UnParmi));
  interp.defineNative("AU_MOINS_UN", makeRule(Rule::Kind::AuMoinsUn));
  interp.defineNative("EXCLUS", makeRule(Rule::Kind::Exclus));
  interp.defineNative("ENSEMBLE", makeRule(Rule::Kind::Ensemble));
  interp.defineNative("PRESENT_PRESENT", makeRule(Rule::Kind::PresentPresent));
  interp.defineNative("PRESENT_ABSENT", makeRule(Rule::Kind::PresentAbsent));
  interp.defineNative("NON_VIDE", makeRule(Rule::Kind::NonVide));
  interp.defineNative("NoRepeat", [](const CallArguments&) -> Value {
    auto o = std::make_shared<SpecObject>();
    o->noRepeat = true;
    return wrap(std::move(o));
  });
  interp.defineNative("TYPES", [&out](const CallArguments& a) -> Value {
    for (const KeywordArgument& k : a.keywords) {
      out.types.addKnown(k.name);
      for (const Value& child : listOf(*k.value)) {
        if (!child.isString()) {
          fail("CATALOG_DEF.26", {});
        }
        out.types.addParent(child.asString(), k.name);
      }
    }
    return Value();
  });
  interp.defineNative("DESCRIPTIONS", [&glossary](const CallArguments& a) -> Value {
    for (const KeywordArgument& k : a.keywords) {
      glossary[k.name] = text(k);
    }
    return Value();
  });

  std::vector<const CatalogFile*> ordered;
  for (const auto& f : files) {
    ordered.push_back(&f);
  }
  std::stable_sort(ordered.begin(), ordered.end(), [](const CatalogFile* a, const CatalogFile* b) {
    bool ca = a->path.rfind("common/", 0) == 0;
    bool cb = b->path.rfind("common/", 0) == 0;
    return ca != cb ? ca : a->path < b->path;
  });
  for (const CatalogFile* f : ordered) {
    auto source = SourceFile::fromText("catalog/commands/" + f->path, f->text);
    RunStatus status = interp.run(source);
    if (!sink.errors.empty() || (status != RunStatus::Completed && status != RunStatus::Finished)) {
      std::string message = "the catalogue file catalog/commands/" + f->path + " is broken";
      for (const auto& d : sink.errors) {
        message += "\n" + formatDiagnostic(d);
      }
      throw InternalError(message, __FILE__, __LINE__);
    }
    if (f->path.rfind("common/", 0) == 0) {
      continue;
    }
    std::string name = stem(f->path);
    auto value = interp.global(name);
    const SpecObject* s = value ? specOf(*value) : nullptr;
    if (s == nullptr || !s->command) {
      throw InternalError("catalog/commands/" + f->path + " must define " + name + " = OPER/MACRO/PROC(...)",
                          __FILE__, __LINE__);
    }
    auto command = std::make_shared<CommandSpec>(*s->command);
    command->name = name;
    command->file = "catalog/commands/" + f->path;
    out.commands[name] = std::move(command);
  }
  // Keywords without fr= take the glossary's description of their name.
  std::function<void(Level&)> describe = [&](Level& level) {
    for (Entry& e : level.entries) {
      if (e.simple && e.simple->description.empty() && glossary.count(e.name)) {
        auto copy = std::make_shared<SimpleSpec>(*e.simple);
        copy->description = glossary[e.name];
        e.simple = copy;
      } else if (e.factor) {
        auto copy = std::make_shared<FactorSpec>(*e.factor);
        if (copy->description.empty() && glossary.count(e.name)) {
          copy->description = glossary[e.name];
        }
        describe(copy->body);
        e.factor = copy;
      } else if (e.block) {
        auto copy = std::make_shared<BlockSpec>(*e.block);
        describe(copy->body);
        e.block = copy;
      }
    }
  };
  for (auto& [name, command] : out.commands) {
    auto copy = std::make_shared<CommandSpec>(*command);
    describe(copy->body);
    command = copy;
  }
  return out;
}

} // namespace stella
