// Validation of one command call against its catalogue entry (see Validator.hpp).
#include "Validator.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace stella {

namespace {

std::string joinNames(const std::vector<std::string>& names, const std::string& sep = ", ") {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += (i ? sep : "") + names[i];
  }
  return out;
}

std::string joinValues(const ValueList& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += (i ? ", " : "") + values[i].repr();
  }
  return out;
}

// A value as seen by block conditions: one value stays a scalar, several are a tuple.
Value conditionValue(const ValueList& values) {
  return values.size() == 1 ? values.front() : Value::tuple(values);
}

bool isSeq(const Value& v) {
  return v.isSequence();
}

bool contains(const Value& haystack, const Value& needle) {
  if (isSeq(haystack)) {
    const auto& items = haystack.items();
    return std::any_of(items.begin(), items.end(), [&](const Value& x) { return x.equals(needle); });
  }
  return haystack.equals(needle);
}

// equal_to / is_in semantics: true when any value of the keyword is (one of) the wanted value(s).
bool matches(const Value& given, const Value& wanted) {
  if (given.isNone()) {
    return false;
  }
  if (isSeq(given)) {
    const auto& items = given.items();
    return std::any_of(items.begin(), items.end(), [&](const Value& x) { return contains(wanted, x); });
  }
  return contains(wanted, given);
}

std::string nameArgument(const CallArguments& args, const char* helper) {
  if (args.positional.empty() || !args.positional.front().isString()) {
    throw UserError(
        Diagnostic::fatal("CATALOG_40", std::string(helper) + "() expects a keyword name as first argument"));
  }
  return args.positional.front().asString();
}

} // namespace

CompiledExpression::Lookup levelLookup(const std::map<std::string, Value>& values,
                                       const ConceptTypes& types) {
  auto valueOf = [&values](const std::string& name) -> Value {
    auto it = values.find(name);
    return it == values.end() ? Value() : it->second;
  };
  return [&values, &types, valueOf](const std::string& name) -> std::optional<Value> {
    if (auto it = values.find(name); it != values.end()) {
      return it->second;
    }
    if (name == "equal_to" || name == "is_in") {
      return makeNativeFunction(name, [valueOf, name](const CallArguments& a) -> Value {
        std::string kw = nameArgument(a, name.c_str());
        if (a.positional.size() != 2) {
          throw UserError(Diagnostic::fatal("CATALOG_40", name + "() expects a keyword name and a value"));
        }
        return Value(matches(valueOf(kw), a.positional[1]));
      });
    }
    if (name == "exists") {
      return makeNativeFunction(name, [valueOf](const CallArguments& a) -> Value {
        return Value(!valueOf(nameArgument(a, "exists")).isNone());
      });
    }
    if (name == "value") {
      return makeNativeFunction(
          name, [valueOf](const CallArguments& a) -> Value { return valueOf(nameArgument(a, "value")); });
    }
    if (name == "first") { // the first value of a keyword (None when absent)
      return makeNativeFunction(name, [valueOf](const CallArguments& a) -> Value {
        Value v = valueOf(nameArgument(a, "first"));
        return isSeq(v) ? (v.items().empty() ? Value() : v.items().front()) : v;
      });
    }
    if (name == "is_type") {
      return makeNativeFunction(name, [valueOf](const CallArguments& a) -> Value {
        Value v = valueOf(nameArgument(a, "is_type"));
        if (isSeq(v) && !v.items().empty()) {
          v = v.items().front();
        }
        return v.isConcept() ? Value(v.asConcept()->type) : Value();
      });
    }
    if (name == "type") { // `type(X) not in (list, tuple)` in a few conditions
      return makeNativeFunction(name, [](const CallArguments& a) -> Value {
        return a.positional.empty() ? Value() : Value(isSeq(a.positional[0]) ? "tuple" : "scalar");
      });
    }
    if (name == "list" || name == "tuple") {
      return Value("tuple");
    }
    if (name == "True") {
      return Value(true);
    }
    if (name == "False") {
      return Value(false);
    }
    if (types.known(name)) {
      return Value(name);
    }
    if (std::any_of(name.begin(), name.end(), [](char c) { return c >= 'a' && c <= 'z'; })) {
      return std::nullopt; // not a keyword: the expression's built-ins (abs, len, sqrt...)
    }
    return Value(); // a keyword of this level that is absent
  };
}

bool evaluateCondition(const CompiledExpression& condition, const CompiledExpression::Lookup& lookup) {
  try {
    return condition.evaluate(lookup).truthy();
  } catch (const UserError& e) {
    STELLA_ASSERT(false, "catalogue condition '" + condition.text() + "' failed: " + e.first().message);
  }
  return false;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

namespace {

// The keywords a level offers under the current values: active definitions in order, and the
// rules of the level and of its active blocks.
struct ActiveSet {
  std::vector<const Entry*> order;
  std::map<std::string, const Entry*> byName;
  std::vector<const Rule*> rules;
};

// Every keyword a level could define, with the conditions of the blocks holding it.
void collectAll(const Level& level, const std::string& condition,
                std::vector<std::pair<std::string, std::string>>& out) {
  for (const Entry& e : level.entries) {
    if (e.block) {
      std::string c =
          condition.empty() ? e.block->conditionText : condition + " and " + e.block->conditionText;
      collectAll(e.block->body, c, out);
    } else {
      out.emplace_back(e.name, condition);
    }
  }
}

class CallValidator {
public:
  CallValidator(const CommandSpec& command, const ConceptTypes& types) : command_(command), types_(types) {}

  ValidatedCall run(const CallArguments& args) {
    for (std::size_t i = 0; i < args.positional.size(); ++i) {
      error("CATALOG_13", command_.name + " takes keyword arguments only",
            i < args.positionalLocations.size() ? args.positionalLocations[i] : args.callLocation);
    }
    ValidatedCall out;
    std::vector<KeywordArgument> keywords;
    const KeywordArgument* reuse = nullptr;
    for (const KeywordArgument& k : args.keywords) {
      if (k.name == "reuse") {
        reuse = &k;
      } else {
        keywords.push_back(k);
      }
    }
    out.keywords = validateLevel(command_.body, keywords, args.callLocation, command_.name);
    checkReuse(reuse, out, args.callLocation);
    if (errors_.empty()) {
      out.resultType = resultType(out.keywords);
    }
    if (!errors_.empty()) {
      // In reading order (a missing keyword is located at its _F, before the keywords inside).
      std::stable_sort(errors_.begin(), errors_.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return std::tie(a.location.line, a.location.column) < std::tie(b.location.line, b.location.column);
      });
      throw UserError(std::move(errors_));
    }
    return out;
  }

private:
  const CommandSpec& command_;
  const ConceptTypes& types_;
  std::vector<Diagnostic> errors_;
  std::vector<std::vector<std::pair<const FactorSpec*, std::string>>> variants_; // per factor being validated

  void error(const std::string& id, std::string message, const SourceLocation& at,
             std::vector<std::string> notes = {}) {
    Diagnostic d = Diagnostic::syntax(id, std::move(message), at);
    for (auto& n : notes) {
      d.withNote(std::move(n));
    }
    errors_.push_back(std::move(d));
  }

  void checkReuse(const KeywordArgument* reuse, ValidatedCall& out, const SourceLocation& call) {
    if (reuse == nullptr) {
      if (command_.reentrant == 'o') {
        std::string target = "the concept it modifies";
        if (const SimpleKeyword* k = out.keywords.simple(command_.reuseKeyword);
            k != nullptr && !k->values.empty() && k->values.front().isConcept()) {
          target = k->values.front().asConcept()->name;
        }
        error("CATALOG_11",
              command_.name + " modifies " + target + " in place: write " + target + " = " + command_.name +
                  "(reuse=" + target + ", ...)",
              call);
      }
      return;
    }
    if (command_.reentrant == 'n') {
      error("CATALOG_11", command_.name + " does not accept reuse=: it always creates a new concept",
            reuse->location);
      return;
    }
    if (!reuse->value || !reuse->value->isConcept()) {
      error("CATALOG_11",
            "reuse= expects a concept, got " + (reuse->value ? reuse->value->repr() : "nothing"),
            reuse->valueLocation);
      return;
    }
    out.reused = reuse->value->asConcept();
    if (!command_.reuseKeyword.empty() && out.keywords.has(command_.reuseKeyword)) {
      const SimpleKeyword* k = out.keywords.simple(command_.reuseKeyword);
      if (k && !k->values.empty() && k->values.front().isConcept() &&
          k->values.front().asConcept() != out.reused) {
        error("CATALOG_11",
              "reuse=" + out.reused->name + " must be the concept given to " + command_.reuseKeyword + " (" +
                  k->values.front().asConcept()->name + ")",
              reuse->valueLocation);
      }
    }
  }

  std::string resultType(const KeywordTree& tree) {
    for (const auto& from : command_.resultFrom) {
      if (const SimpleKeyword* k = tree.simple(from);
          k && !k->values.empty() && k->values.front().isConcept()) {
        return k->values.front().asConcept()->type;
      }
    }
    if (!command_.resultCases.empty()) {
      std::map<std::string, Value> values;
      for (const auto& s : tree.simples()) {
        values[s.name] = conditionValue(s.values);
      }
      for (const auto& f : tree.factors()) {
        values[f.name] = Value(true);
      }
      auto lookup = levelLookup(values, types_);
      for (const auto& [condition, type] : command_.resultCases) {
        if (evaluateCondition(*condition, lookup)) {
          return type;
        }
      }
    }
    return command_.resultType;
  }

  ActiveSet collectActive(const Level& level, const CompiledExpression::Lookup& lookup) {
    ActiveSet a;
    addActive(level, lookup, a);
    return a;
  }

  void addActive(const Level& level, const CompiledExpression::Lookup& lookup, ActiveSet& a) {
    for (const Rule& r : level.rules) {
      a.rules.push_back(&r);
    }
    for (const Entry& e : level.entries) {
      if (e.block) {
        if (evaluateCondition(*e.block->condition, lookup)) {
          addActive(e.block->body, lookup, a);
        }
      } else if (a.byName.emplace(e.name, &e).second) {
        a.order.push_back(&e);
      }
    }
  }

  // Fixed point of "block conditions read keyword values, active blocks bring defaults".
  ActiveSet settle(const Level& level, const std::map<std::string, Value>& given,
                   std::map<std::string, Value>& env, std::map<std::string, Value>& ruleDefaults) {
    env = given;
    ActiveSet active;
    for (int iteration = 0; iteration < 32; ++iteration) {
      active = collectActive(level, levelLookup(env, types_));
      std::map<std::string, Value> next = given;
      ruleDefaults.clear();
      for (const Rule* r : active.rules) {
        if (r->defaults.empty()) {
          continue;
        }
        bool any = std::any_of(r->names.begin(), r->names.end(),
                               [&](const std::string& n) { return next.count(n) > 0; });
        if (!any) {
          for (const auto& [name, value] : r->defaults) {
            next[name] = value;
            ruleDefaults[name] = value;
          }
        }
      }
      for (const Entry* e : active.order) {
        if (e->simple && e->simple->defaultValue && next.count(e->name) == 0) {
          next[e->name] = conditionValue(*e->simple->defaultValue);
        }
      }
      bool same = next.size() == env.size() && std::all_of(next.begin(), next.end(), [&](const auto& kv) {
                    auto it = env.find(kv.first);
                    return it != env.end() && it->second.equals(kv.second);
                  });
      env = std::move(next);
      if (same) {
        break;
      }
    }
    return active;
  }

  KeywordTree validateLevel(const Level& level, const std::vector<KeywordArgument>& written,
                            const SourceLocation& at, const std::string& where) {
    // As in code_aster, a keyword given the value None is absent (command files build
    // arguments programmatically: `INST=None`).
    std::vector<KeywordArgument> keywords;
    for (const KeywordArgument& k : written) {
      if (k.value && !k.value->isNone()) {
        keywords.push_back(k);
      }
    }
    KeywordTree tree;
    tree.setLocation(at);
    std::map<std::string, Value> given;
    std::map<std::string, const KeywordArgument*> givenArgs;
    for (const KeywordArgument& k : keywords) {
      if (givenArgs.count(k.name)) {
        error("CATALOG_15", "keyword " + k.name + " is given twice in " + where, k.location);
        continue;
      }
      given[k.name] = k.value ? *k.value : Value();
      givenArgs[k.name] = &k;
    }
    std::map<std::string, Value> env;
    std::map<std::string, Value> ruleDefaults;
    ActiveSet active = settle(level, given, env, ruleDefaults);

    std::size_t errorsBefore = errors_.size();
    std::vector<std::string> present;
    auto noteRename = [&](const std::string& name, const std::string& stored, const SourceLocation& loc) {
      if (stored == name) {
        return;
      }
      present.push_back(stored); // rules written with the current spelling see the old one too
      if (givenArgs.count(stored)) {
        error("CATALOG_15",
              name + " and " + stored + " are the same keyword (" + name +
                  " is the older spelling); give only one",
              loc);
      }
    };
    for (const Entry* e : active.order) {
      auto g = givenArgs.find(e->name);
      if (e->simple) {
        const SimpleSpec& s = *e->simple;
        std::string stored = s.renamedTo.empty() ? e->name : s.renamedTo;
        if (g != givenArgs.end()) {
          present.push_back(e->name);
          noteRename(e->name, stored, g->second->location);
          if (refuseNotImplemented(e->name, s, *g->second, where)) {
            continue;
          }
          if (auto values = checkSimple(e->name, s, *g->second, where)) {
            tree.addSimple(SimpleKeyword{stored, std::move(*values), g->second->location, false});
          }
        } else if (auto rd = ruleDefaults.find(e->name); rd != ruleDefaults.end()) {
          present.push_back(e->name);
          tree.addSimple(SimpleKeyword{stored, normalised(s, rd->second), at, true});
        } else if (s.defaultValue) {
          present.push_back(e->name);
          tree.addSimple(SimpleKeyword{stored, normalised(s, conditionValue(*s.defaultValue)), at, true});
        } else if (s.presence == Presence::Mandatory) {
          error("CATALOG_5", "missing mandatory keyword " + e->name + " in " + where, at,
                {e->name + ": " + s.description});
        }
      } else if (e->factor) {
        const FactorSpec& f = *e->factor;
        std::string stored = f.renamedTo.empty() ? e->name : f.renamedTo;
        if (g != givenArgs.end()) {
          present.push_back(e->name);
          noteRename(e->name, stored, g->second->location);
          if (f.notImplemented) {
            notImplementedYet("keyword " + e->name + " of " + where, *f.notImplemented, g->second->location);
            continue;
          }
          // The other definitions of this factor keyword in exclusive blocks of this level, to
          // tell a user which variant a misplaced keyword belongs to.
          std::vector<std::pair<const FactorSpec*, std::string>> variants;
          collectVariants(level, e->name, &f, "", variants);
          variants_.push_back(std::move(variants));
          auto occurrences = checkFactor(e->name, f, *g->second, where);
          variants_.pop_back();
          tree.addFactor(FactorKeyword{stored, std::move(occurrences), g->second->location, false});
        } else if (f.presence == Presence::Defaulted) {
          present.push_back(e->name);
          std::vector<KeywordTree> one;
          one.push_back(validateLevel(f.body, {}, at, e->name + " of " + where));
          tree.addFactor(FactorKeyword{stored, std::move(one), at, true});
        } else if (f.presence == Presence::Mandatory) {
          error("CATALOG_5", "missing mandatory factor keyword " + e->name + " in " + where, at,
                {e->name + ": " + f.description, "write " + e->name + "=_F(...)"});
        }
      }
    }
    // Keywords not offered here. When a value of this level was wrong, the blocks it selects
    // are unknown: "not allowed here" would then only be a consequence, so it is not reported.
    bool valueErrors = errors_.size() != errorsBefore;
    for (const KeywordArgument& k : keywords) {
      if (active.byName.count(k.name) == 0) {
        if (level.freeKeywords) {
          tree.addSimple(SimpleKeyword{k.name, items(k.value ? *k.value : Value()), k.location, false});
        } else {
          reportNotAllowed(level, active, k, where, valueErrors);
        }
      }
    }
    checkRules(active, present, at, where);
    return tree;
  }

  void notImplementedYet(const std::string& what, const std::string& why, const SourceLocation& at,
                         std::vector<std::string> notes = {}) {
    if (!why.empty()) {
      notes.insert(notes.begin(), why);
    }
    notes.push_back("`stella catalog " + command_.name + "` shows what stella implements of it");
    Diagnostic d = Diagnostic::fatal("CATALOG_17", what + " is not implemented yet", at);
    for (auto& n : notes) {
      d.withNote(std::move(n));
    }
    errors_.push_back(std::move(d));
  }

  // A keyword the catalogue marks non_implemente= given by the user: refused unless its value is
  // the one accepted (accepte=, the keyword's default).
  bool refuseNotImplemented(const std::string& name, const SimpleSpec& s, const KeywordArgument& k,
                            const std::string& where) {
    if (!s.notImplemented) {
      return false;
    }
    if (s.acceptedValue && k.value) {
      ValueList given = items(*k.value);
      if (given.size() == 1 && (given.front().equals(*s.acceptedValue) ||
                                (given.front().isNumber() && s.acceptedValue->isNumber() &&
                                 given.front().asReal() == s.acceptedValue->asReal()))) {
        return false;
      }
    }
    std::vector<std::string> notes;
    if (s.acceptedValue) {
      notes.push_back("only " + name + "=" + s.acceptedValue->repr() + " is accepted (or leave it out)");
    }
    notImplementedYet("keyword " + name + " of " + where, *s.notImplemented, k.location, std::move(notes));
    return true;
  }

  static void collectVariants(const Level& level, const std::string& name, const FactorSpec* self,
                              const std::string& condition,
                              std::vector<std::pair<const FactorSpec*, std::string>>& out) {
    for (const Entry& e : level.entries) {
      if (e.block) {
        std::string c =
            condition.empty() ? e.block->conditionText : condition + " and " + e.block->conditionText;
        collectVariants(e.block->body, name, self, c, out);
      } else if (e.factor && e.name == name && e.factor.get() != self) {
        out.emplace_back(e.factor.get(), condition.empty() ? "(always)" : condition);
      }
    }
  }

  void reportNotAllowed(const Level& level, const ActiveSet& active, const KeywordArgument& k,
                        const std::string& where, bool quietIfConditional) {
    if (std::find(level.outOfScope.begin(), level.outOfScope.end(), k.name) != level.outOfScope.end()) {
      error("CATALOG_SCOPE",
            "keyword " + k.name + " of " + where + " belongs to physics outside stella's scope", k.location,
            {"stella covers static and dynamic mechanics with contact; this keyword of the reference "
             "catalogue is not provided"});
      return;
    }
    std::vector<std::pair<std::string, std::string>> all;
    collectAll(level, "", all);
    for (const auto& [name, condition] : all) {
      if (name == k.name) {
        if (quietIfConditional) {
          return;
        }
        error("CATALOG_14",
              "keyword " + k.name + " is not allowed here in " + where + ": it requires " + condition,
              k.location);
        return;
      }
    }
    std::vector<std::string> names;
    for (const auto& [name, condition] : all) {
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        names.push_back(name);
      }
    }
    std::vector<std::pair<std::size_t, std::string>> near;
    for (const auto& n : names) {
      std::size_t d = editDistance(n, k.name);
      if (d <= std::max<std::size_t>(2, k.name.size() / 4)) {
        near.emplace_back(d, n);
      }
    }
    std::sort(near.begin(), near.end());
    std::vector<std::string> notes;
    if (!near.empty()) {
      std::string s = "did you mean ";
      for (std::size_t i = 0; i < near.size() && i < 3; ++i) {
        s += (i ? " or '" : "'") + near[i].second + "'";
      }
      notes.push_back(s + "?");
    }
    std::vector<std::string> allowed;
    for (const Entry* e : active.order) {
      allowed.push_back(e->name);
    }
    if (!variants_.empty()) {
      for (const auto& [variant, condition] : variants_.back()) {
        std::vector<std::pair<std::string, std::string>> inVariant;
        collectAll(variant->body, "", inVariant);
        bool found =
            std::any_of(inVariant.begin(), inVariant.end(), [&](const auto& p) { return p.first == k.name; });
        if (found) {
          notes.push_back(k.name + " belongs to the variant of this factor keyword used when " + condition);
          break;
        }
      }
    }
    notes.push_back("keywords allowed here: " + joinNames(allowed));
    error("CATALOG_1", "unknown keyword " + k.name + " in " + where, k.location, std::move(notes));
  }

  static ValueList items(const Value& v) { return v.isSequence() ? v.items() : ValueList{v}; }

  // A default or rule default, normalised like a user value (ints to reals for 'R').
  static ValueList normalised(const SimpleSpec& s, const Value& v) {
    ValueList out = items(v);
    if (std::find(s.types.begin(), s.types.end(), "R") != s.types.end()) {
      for (Value& x : out) {
        if (x.isInt()) {
          x = Value(x.asReal());
        }
      }
    }
    return out;
  }

  std::string expectedTypes(const SimpleSpec& s) {
    std::vector<std::string> words;
    for (const auto& t : s.types) {
      words.push_back(typeDescription(t));
    }
    return joinNames(words, " or ");
  }

  // Converts one value to the spec's type; nullopt when it does not fit.
  std::optional<Value> convert(const SimpleSpec& s, const Value& v) {
    for (const auto& t : s.types) {
      if (t == "R") {
        if (v.isReal()) {
          return v;
        }
        if (v.isInt()) {
          return Value(v.asReal());
        }
      } else if (t == "I") {
        if (v.isInt()) {
          return v;
        }
      } else if (t == "C") {
        if (v.kind() == Value::Kind::Complex) {
          return v;
        }
        if (v.isInt() || v.isReal()) {
          return Value(std::complex<double>(v.asReal(), 0.0));
        }
      } else if (t == "TXM" || t == "grma" || t == "grno" || t == "ma" || t == "no") {
        if (v.isString()) {
          return v;
        }
      } else if (v.isConcept() && (t == "assd" || v.asConcept()->type == kUncheckedConceptType ||
                                   types_.isA(v.asConcept()->type, t))) {
        return v;
      }
    }
    return std::nullopt;
  }

  std::string countText(const SimpleSpec& s) {
    if (s.max == s.min) {
      return s.min == 1 ? "a single value" : std::to_string(s.min) + " values";
    }
    if (s.max == kUnbounded) {
      return "at least " + std::to_string(s.min) + (s.min == 1 ? " value" : " values");
    }
    return "between " + std::to_string(s.min) + " and " + std::to_string(s.max) + " values";
  }

  std::optional<ValueList> checkSimple(const std::string& name, const SimpleSpec& s, const KeywordArgument& k,
                                       const std::string& where) {
    const Value& raw = k.value ? *k.value : Value();
    if (s.oldFactorForm && (raw.isFactor() || raw.isDict())) {
      FactorSpec f = *s.oldFactorForm;
      checkFactor(name, f, k, where);
      return ValueList{s.oldFactorValue.value_or(Value("OUI"))};
    }
    if (raw.isFactor() || raw.isDict()) {
      error("CATALOG_2", name + " expects " + expectedTypes(s) + ", got a factor keyword occurrence _F(...)",
            k.valueLocation);
      return std::nullopt;
    }
    ValueList given = items(raw);
    std::size_t errorsBefore = errors_.size();
    if (given.size() < static_cast<std::size_t>(s.min) ||
        (s.max != kUnbounded && given.size() > static_cast<std::size_t>(s.max))) {
      error("CATALOG_4",
            std::string(given.size() < static_cast<std::size_t>(s.min) ? "too few" : "too many") +
                " values for " + name + ": expected " + countText(s) + ", got " +
                std::to_string(given.size()),
            k.valueLocation);
    }
    ValueList out;
    for (const Value& v : given) {
      auto converted = convert(s, v);
      if (!converted) {
        if (v.isConcept() && !s.isConceptType()) {
          error("CATALOG_2",
                name + " expects " + expectedTypes(s) + ", got the concept " + v.asConcept()->name + " (a " +
                    v.asConcept()->type + ")",
                k.valueLocation);
        } else if (v.isConcept() || s.isConceptType()) {
          std::string got =
              v.isConcept() ? v.asConcept()->name + " is a " + v.asConcept()->type : "got " + v.repr();
          error("CATALOG_7", name + " expects " + joinNames(s.types, " or ") + "; " + got, k.valueLocation);
        } else {
          error("CATALOG_2", name + " expects " + expectedTypes(s) + ", got " + v.repr(), k.valueLocation);
        }
        continue;
      }
      if (converted->isConcept() && converted->asConcept()->destroyed) {
        error("CATALOG_16",
              name + ": the concept " + converted->asConcept()->name + " was destroyed by DETRUIRE",
              k.valueLocation);
        continue;
      }
      if (std::any_of(s.outOfScopeValues.begin(), s.outOfScopeValues.end(),
                      [&](const Value& x) { return x.equals(*converted); })) {
        error("CATALOG_SCOPE",
              name + " = " + converted->repr() + " belongs to physics outside stella's scope",
              k.valueLocation, {"allowed: " + joinValues(s.into)});
        continue;
      }
      if (!s.into.empty() && std::none_of(s.into.begin(), s.into.end(),
                                          [&](const Value& allowed) { return allowed.equals(*converted); })) {
        std::vector<std::string> near;
        if (converted->isString()) {
          std::size_t best = 3; // suggest only the closest allowed values, at most 2 edits away
          std::string names;
          for (const auto& a : s.into) {
            if (!a.isString()) {
              continue;
            }
            std::size_t d = editDistance(a.asString(), converted->asString());
            if (d < best) {
              best = d;
              names = a.repr();
            } else if (d == best) {
              names += " or " + a.repr();
            }
          }
          if (!names.empty()) {
            near.push_back("did you mean " + names + "?");
          }
        }
        error("CATALOG_3",
              name + " = " + converted->repr() + " is not an allowed value; allowed: " + joinValues(s.into),
              k.valueLocation, near);
        continue;
      }
      if (!s.implementedValues.empty() &&
          std::none_of(s.implementedValues.begin(), s.implementedValues.end(),
                       [&](const Value& done) { return done.equals(*converted); })) {
        std::vector<std::string> notes{"implemented: " + joinValues(s.implementedValues)};
        if (!s.stellaNote.empty()) {
          notes.push_back(s.stellaNote);
        }
        notImplementedYet(name + "=" + converted->repr() + " in " + where, "", k.valueLocation,
                          std::move(notes));
        continue;
      }
      if (converted->isNumber()) {
        double x = converted->asReal();
        if (s.valMin && x < *s.valMin) {
          error("CATALOG_8",
                name + " = " + converted->repr() + " is below its minimum " + Value(*s.valMin).repr(),
                k.valueLocation);
        }
        if (s.valMax && x > *s.valMax) {
          error("CATALOG_8",
                name + " = " + converted->repr() + " is above its maximum " + Value(*s.valMax).repr(),
                k.valueLocation);
        }
      }
      out.push_back(*converted);
    }
    if (s.noRepeat) {
      for (std::size_t i = 0; i < out.size(); ++i) {
        for (std::size_t j = i + 1; j < out.size(); ++j) {
          if (out[i].equals(out[j])) {
            error("CATALOG_10", name + " lists " + out[i].repr() + " twice; each value may appear only once",
                  k.valueLocation);
            i = out.size();
            break;
          }
        }
      }
    }
    if (errors_.size() != errorsBefore) {
      return std::nullopt;
    }
    return out;
  }

  // The keyword arguments of one occurrence given as _F(...) or as a dict.
  std::optional<std::vector<KeywordArgument>> occurrence(const Value& v, const SourceLocation& at,
                                                         SourceLocation& where) {
    if (v.isFactor()) {
      where = v.asFactor()->location.known() ? v.asFactor()->location : at;
      return v.asFactor()->keywords;
    }
    if (v.isDict()) {
      where = at;
      std::vector<KeywordArgument> out;
      for (const auto& [key, value] : v.asDict()->items) {
        if (!key.isString()) {
          return std::nullopt;
        }
        out.push_back(KeywordArgument{key.asString(), std::make_shared<const Value>(value), at, at});
      }
      return out;
    }
    return std::nullopt;
  }

  std::vector<KeywordTree> checkFactor(const std::string& name, const FactorSpec& f, const KeywordArgument& k,
                                       const std::string& where) {
    const Value& raw = k.value ? *k.value : Value();
    ValueList given = items(raw);
    std::vector<KeywordTree> out;
    if (given.size() < static_cast<std::size_t>(f.min) ||
        (f.max != kUnbounded && given.size() > static_cast<std::size_t>(f.max))) {
      std::string bounds = f.max == kUnbounded ? "at least " + std::to_string(f.min)
                           : f.min == f.max
                               ? std::to_string(f.min)
                               : "between " + std::to_string(f.min) + " and " + std::to_string(f.max);
      error("CATALOG_9",
            std::string(given.size() < static_cast<std::size_t>(f.min) ? "too few" : "too many") +
                " occurrences of " + name + ": expected " + bounds + ", got " + std::to_string(given.size()),
            k.valueLocation);
    }
    for (std::size_t i = 0; i < given.size(); ++i) {
      SourceLocation at;
      auto keywords = occurrence(given[i], k.valueLocation, at);
      if (!keywords) {
        error("CATALOG_2", name + " expects _F(...) occurrences, got " + given[i].repr(), k.valueLocation,
              {"write " + name + "=_F(KEYWORD=value, ...)"});
        continue;
      }
      std::string label =
          name + (given.size() > 1 ? " (occurrence " + std::to_string(i + 1) + ")" : "") + " of " + where;
      out.push_back(validateLevel(f.body, *keywords, at, label));
    }
    return out;
  }

  void checkRules(const ActiveSet& active, const std::vector<std::string>& present, const SourceLocation& at,
                  const std::string& where) {
    for (const Rule* r : active.rules) {
      if (r->holds(present)) {
        continue;
      }
      std::vector<std::string> found;
      for (const auto& n : r->names) {
        if (std::find(present.begin(), present.end(), n) != present.end()) {
          found.push_back(n);
        }
      }
      error("CATALOG_6",
            "rule " + r->keyword() + "(" + joinNames(r->names) + ") of " + where + " is broken: " +
                r->explanation() + (found.empty() ? "; none is given" : "; given: " + joinNames(found)),
            at);
    }
  }
};

} // namespace

ValidatedCall validateCall(const CommandSpec& command, const ConceptTypes& types, const CallArguments& args) {
  return CallValidator(command, types).run(args);
}

} // namespace stella
