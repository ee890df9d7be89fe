// Validation of one command call against its catalogue entry (see Validator.hpp).
#include "CallValidator.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace stella {

namespace validation {

std::string joinNames(const std::vector<std::string>& names, const std::string& sep) {
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

} // namespace validation

namespace {

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
    throw UserError(msg::make("CATALOG_40", {{"helper", std::string(helper)}}));
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
          throw UserError(msg::make("CATALOG_40.2", {{"name", name}}));
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

ValidatedCall validateCall(const CommandSpec& command, const ConceptTypes& types, const CallArguments& args) {
  return validation::CallValidator(command, types).run(args);
}

} // namespace stella
