// Validation of one command call: the values of simple keywords (types, counts, allowed
// values, bounds), and defaults normalised like them (see CallValidator.hpp).
#include "CallValidator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace stella::validation {

ValueList CallValidator::normalised(const SimpleSpec& s, const Value& v) {
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

std::string CallValidator::expectedTypes(const SimpleSpec& s) {
  std::vector<std::string> words;
  for (const auto& t : s.types) {
    words.push_back(typeDescription(t));
  }
  return joinNames(words, " or ");
}

std::optional<Value> CallValidator::convert(const SimpleSpec& s, const Value& v) {
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

std::string CallValidator::countText(const SimpleSpec& s) {
  if (s.max == s.min) {
    return s.min == 1 ? "a single value" : std::to_string(s.min) + " values";
  }
  if (s.max == kUnbounded) {
    return "at least " + std::to_string(s.min) + (s.min == 1 ? " value" : " values");
  }
  return "between " + std::to_string(s.min) + " and " + std::to_string(s.max) + " values";
}

std::optional<ValueList> CallValidator::checkSimple(const std::string& name, const SimpleSpec& s,
                                                    const KeywordArgument& k, const std::string& where) {
  const Value& raw = k.value ? *k.value : Value();
  if (s.oldFactorForm && (raw.isFactor() || raw.isDict())) {
    FactorSpec f = *s.oldFactorForm;
    checkFactor(name, f, k, where);
    return ValueList{s.oldFactorValue.value_or(Value("OUI"))};
  }
  if (raw.isFactor() || raw.isDict()) {
    error("CATALOG_2.2", {{"name", name}, {"expected_types", expectedTypes(s)}}, k.valueLocation);
    return std::nullopt;
  }
  ValueList given = items(raw);
  std::size_t errorsBefore = errors_.size();
  if (given.size() < static_cast<std::size_t>(s.min) ||
      (s.max != kUnbounded && given.size() > static_cast<std::size_t>(s.max))) {
    error("CATALOG_4",
          {{"given_count",
            std::string(given.size() < static_cast<std::size_t>(s.min) ? "too few" : "too many")},
           {"name", name},
           {"count_text", countText(s)},
           {"given_count_2", std::to_string(given.size())}},
          k.valueLocation);
  }
  ValueList out;
  for (const Value& v : given) {
    auto converted = convert(s, v);
    if (!converted) {
      if (v.isConcept() && !s.isConceptType()) {
        error("CATALOG_2.3",
              {{"name", name},
               {"expected_types", expectedTypes(s)},
               {"name_2", v.asConcept()->name},
               {"type", v.asConcept()->type}},
              k.valueLocation);
      } else if (v.isConcept() || s.isConceptType()) {
        std::string got =
            v.isConcept() ? v.asConcept()->name + " is a " + v.asConcept()->type : "got " + v.repr();
        error("CATALOG_7", {{"name", name}, {"join_names", joinNames(s.types, " or ")}, {"got", got}},
              k.valueLocation);
      } else {
        error("CATALOG_2.4", {{"name", name}, {"expected_types", expectedTypes(s)}, {"repr", v.repr()}},
              k.valueLocation);
      }
      continue;
    }
    if (converted->isConcept() && converted->asConcept()->destroyed) {
      error("CATALOG_16", {{"name", name}, {"name_2", converted->asConcept()->name}}, k.valueLocation);
      continue;
    }
    if (std::any_of(s.outOfScopeValues.begin(), s.outOfScopeValues.end(),
                    [&](const Value& x) { return x.equals(*converted); })) {
      error("CATALOG_SCOPE.2",
            {{"name", name}, {"repr", converted->repr()}, {"join_values", joinValues(s.into)}},
            k.valueLocation);
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
      error("CATALOG_3", {{"name", name}, {"repr", converted->repr()}, {"join_values", joinValues(s.into)}},
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
      notImplementedYet("CATALOG_17.value", {{"name", name}, {"value", converted->repr()}, {"where", where}},
                        "", k.valueLocation, std::move(notes));
      continue;
    }
    if (converted->isNumber()) {
      double x = converted->asReal();
      if (s.valMin && x < *s.valMin) {
        error("CATALOG_8", {{"name", name}, {"repr", converted->repr()}, {"repr_2", Value(*s.valMin).repr()}},
              k.valueLocation);
      }
      if (s.valMax && x > *s.valMax) {
        error("CATALOG_8.2",
              {{"name", name}, {"repr", converted->repr()}, {"repr_2", Value(*s.valMax).repr()}},
              k.valueLocation);
      }
    }
    out.push_back(*converted);
  }
  if (s.noRepeat) {
    for (std::size_t i = 0; i < out.size(); ++i) {
      for (std::size_t j = i + 1; j < out.size(); ++j) {
        if (out[i].equals(out[j])) {
          error("CATALOG_10", {{"name", name}, {"repr", out[i].repr()}}, k.valueLocation);
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

} // namespace stella::validation
