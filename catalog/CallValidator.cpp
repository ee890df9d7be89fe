// Validation of one command call: the levels, their active blocks and defaults, reuse= and
// the result type (see CallValidator.hpp).
#include "CallValidator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace stella::validation {

ValidatedCall CallValidator::run(const CallArguments& args) {
  for (std::size_t i = 0; i < args.positional.size(); ++i) {
    error("CATALOG_13", {{"name", command_.name}},
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

void CallValidator::error(std::string_view key, msg::Args args, const SourceLocation& at,
                          std::vector<std::string> notes) {
  Diagnostic d = msg::make(key, args, at);
  for (auto& n : notes) {
    d.withNote(std::move(n));
  }
  errors_.push_back(std::move(d));
}

void CallValidator::checkReuse(const KeywordArgument* reuse, ValidatedCall& out, const SourceLocation& call) {
  if (reuse == nullptr) {
    if (command_.reentrant == 'o') {
      std::string target = "the concept it modifies";
      if (const SimpleKeyword* k = out.keywords.simple(command_.reuseKeyword);
          k != nullptr && !k->values.empty() && k->values.front().isConcept()) {
        target = k->values.front().asConcept()->name;
      }
      error("CATALOG_11", {{"name", command_.name}, {"target", target}}, call);
    }
    return;
  }
  if (command_.reentrant == 'n') {
    error("CATALOG_11.2", {{"name", command_.name}}, reuse->location);
    return;
  }
  if (!reuse->value || !reuse->value->isConcept()) {
    error("CATALOG_11.3", {{"value", (reuse->value ? reuse->value->repr() : "nothing")}},
          reuse->valueLocation);
    return;
  }
  out.reused = reuse->value->asConcept();
  if (!command_.reuseKeyword.empty() && out.keywords.has(command_.reuseKeyword)) {
    const SimpleKeyword* k = out.keywords.simple(command_.reuseKeyword);
    if (k && !k->values.empty() && k->values.front().isConcept() &&
        k->values.front().asConcept() != out.reused) {
      error("CATALOG_11.4",
            {{"name", out.reused->name},
             {"reuse_keyword", command_.reuseKeyword},
             {"name_2", k->values.front().asConcept()->name}},
            reuse->valueLocation);
    }
  }
}

std::string CallValidator::resultType(const KeywordTree& tree) {
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

ActiveSet CallValidator::collectActive(const Level& level, const CompiledExpression::Lookup& lookup) {
  ActiveSet a;
  addActive(level, lookup, a);
  return a;
}

void CallValidator::addActive(const Level& level, const CompiledExpression::Lookup& lookup, ActiveSet& a) {
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

ActiveSet CallValidator::settle(const Level& level, const std::map<std::string, Value>& given,
                                std::map<std::string, Value>& env,
                                std::map<std::string, Value>& ruleDefaults) {
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

KeywordTree CallValidator::validateLevel(const Level& level, const std::vector<KeywordArgument>& written,
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
      error("CATALOG_15", {{"name", k.name}, {"where", where}}, k.location);
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
      error("CATALOG_15.2", {{"name", name}, {"stored", stored}}, loc);
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
        error("CATALOG_5", {{"name", e->name}, {"where", where}, {"description", s.description}}, at);
      }
    } else if (e->factor) {
      const FactorSpec& f = *e->factor;
      std::string stored = f.renamedTo.empty() ? e->name : f.renamedTo;
      if (g != givenArgs.end()) {
        present.push_back(e->name);
        noteRename(e->name, stored, g->second->location);
        if (f.notImplemented) {
          notImplementedYet("CATALOG_17.keyword", {{"name", e->name}, {"where", where}}, *f.notImplemented,
                            g->second->location);
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
        error("CATALOG_5.2", {{"name", e->name}, {"where", where}, {"description", f.description}}, at);
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

} // namespace stella::validation
