// Helpers shared by the built-in functions and the math module: argument count and keyword checks
// with Python's messages, and the built-ins over sequences that the dispatcher in Builtins.cpp calls.
#pragma once

#include "Evaluator.hpp"

#include <initializer_list>
#include <string>

namespace stella::builtins {

inline void arity(const CallArguments& a, const std::string& name, std::size_t min, std::size_t max) {
  if (a.positional.size() < min || a.positional.size() > max) {
    std::string expected =
        min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max);
    if (max == min + 1000) {
      expected = "at least " + std::to_string(min);
    }
    langError(
        "LANG_ARGS.12",
        {{"name", name}, {"expected", expected}, {"positional_count", std::to_string(a.positional.size())}});
  }
}

inline void onlyKeywords(const CallArguments& a, const std::string& name,
                         std::initializer_list<const char*> allowed) {
  for (const auto& kw : a.keywords) {
    bool ok = false;
    for (const char* k : allowed) {
      ok = ok || kw.name == k;
    }
    if (!ok) {
      langError("LANG_ARGS.6", {{"name", name}, {"name_2", kw.name}});
    }
  }
}

inline const Value* keyword(const CallArguments& a, const char* name) {
  const KeywordArgument* kw = a.find(name);
  return kw != nullptr ? kw->value.get() : nullptr;
}

// BuiltinSequences.cpp
Value makeRange(const CallArguments& a);
Value length(const Value& v);
Value extreme(Evaluator& ev, const CallArguments& a, const Pos& at, bool wantMax);
Value sum(Evaluator& ev, const CallArguments& a);
Value zip(Evaluator& ev, const CallArguments& a);
Value enumerate(Evaluator& ev, const CallArguments& a);
Value sorted(Evaluator& ev, const CallArguments& a, const Pos& at);
Value callEach(Evaluator& ev, const CallArguments& a, const Pos& at, bool filter);

} // namespace stella::builtins
