// Validation of one command call: factor keywords and their occurrences, the rules of a level,
// and the keywords refused (not implemented, not offered here) with their suggestions (see
// CallValidator.hpp).
#include "CallValidator.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace stella::validation {

namespace {

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

} // namespace

void CallValidator::notImplementedYet(std::string_view key, msg::Args args, const std::string& why,
                                      const SourceLocation& at, std::vector<std::string> notes) {
  if (!why.empty()) {
    notes.insert(notes.begin(), why);
  }
  notes.push_back(msg::text("CATALOG_17.n1", {{"command", command_.name}}));
  Diagnostic d = msg::make(key, args, at);
  for (auto& n : notes) {
    d.withNote(std::move(n));
  }
  errors_.push_back(std::move(d));
}

bool CallValidator::refuseNotImplemented(const std::string& name, const SimpleSpec& s,
                                         const KeywordArgument& k, const std::string& where) {
  if (!s.notImplemented) {
    return false;
  }
  if (s.acceptedValue && k.value) {
    ValueList given = items(*k.value);
    if (given.size() == 1 &&
        (given.front().equals(*s.acceptedValue) || (given.front().isNumber() && s.acceptedValue->isNumber() &&
                                                    given.front().asReal() == s.acceptedValue->asReal()))) {
      return false;
    }
  }
  std::vector<std::string> notes;
  if (s.acceptedValue) {
    notes.push_back(msg::text("CATALOG_17.n_accepted", {{"name", name}, {"value", s.acceptedValue->repr()}}));
  }
  notImplementedYet("CATALOG_17.keyword", {{"name", name}, {"where", where}}, *s.notImplemented, k.location,
                    std::move(notes));
  return true;
}

void CallValidator::collectVariants(const Level& level, const std::string& name, const FactorSpec* self,
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

void CallValidator::reportNotAllowed(const Level& level, const ActiveSet& active, const KeywordArgument& k,
                                     const std::string& where, bool quietIfConditional) {
  if (std::find(level.outOfScope.begin(), level.outOfScope.end(), k.name) != level.outOfScope.end()) {
    error("CATALOG_SCOPE", {{"name", k.name}, {"where", where}}, k.location);
    return;
  }
  std::vector<std::pair<std::string, std::string>> all;
  collectAll(level, "", all);
  for (const auto& [name, condition] : all) {
    if (name == k.name) {
      if (quietIfConditional) {
        return;
      }
      error("CATALOG_14", {{"name", k.name}, {"where", where}, {"condition", condition}}, k.location);
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
    std::string choices;
    for (std::size_t i = 0; i < near.size() && i < 3; ++i) {
      choices += (i ? " or '" : "'") + near[i].second + "'";
    }
    notes.push_back(msg::text("CATALOG_1.n_mean", {{"choices", choices}}));
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
        notes.push_back(msg::text("CATALOG_1.n_variant", {{"name", k.name}, {"condition", condition}}));
        break;
      }
    }
  }
  notes.push_back(msg::text("CATALOG_1.n_allowed", {{"names", joinNames(allowed)}}));
  error("CATALOG_1", {{"name", k.name}, {"where", where}}, k.location, std::move(notes));
}

std::optional<std::vector<KeywordArgument>>
CallValidator::occurrence(const Value& v, const SourceLocation& at, SourceLocation& where) {
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

std::vector<KeywordTree> CallValidator::checkFactor(const std::string& name, const FactorSpec& f,
                                                    const KeywordArgument& k, const std::string& where) {
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
          {{"given_count",
            std::string(given.size() < static_cast<std::size_t>(f.min) ? "too few" : "too many")},
           {"name", name},
           {"bounds", bounds},
           {"given_count_2", std::to_string(given.size())}},
          k.valueLocation);
  }
  for (std::size_t i = 0; i < given.size(); ++i) {
    SourceLocation at;
    auto keywords = occurrence(given[i], k.valueLocation, at);
    if (!keywords) {
      error("CATALOG_2", {{"name", name}, {"repr", given[i].repr()}}, k.valueLocation);
      continue;
    }
    std::string label =
        name + (given.size() > 1 ? " (occurrence " + std::to_string(i + 1) + ")" : "") + " of " + where;
    out.push_back(validateLevel(f.body, *keywords, at, label));
  }
  return out;
}

void CallValidator::checkRules(const ActiveSet& active, const std::vector<std::string>& present,
                               const SourceLocation& at, const std::string& where) {
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
          {{"keyword", r->keyword()},
           {"join_names", joinNames(r->names)},
           {"where", where},
           {"explanation", r->explanation()},
           {"value", (found.empty() ? "; none is given" : "; given: " + joinNames(found))}},
          at);
  }
}

} // namespace stella::validation
