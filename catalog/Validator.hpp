#pragma once
// Validation of one command call against its catalogue entry: turns the user's keyword
// arguments into a typed, complete KeywordTree (defaults filled in active blocks, 'd' factor
// keywords created, values normalised to lists, integers converted where a real is expected)
// and collects every error of the call (CATALOG_n message ids, located at the keyword).

#include "Catalog.hpp"
#include "CommandSpec.hpp"

#include <optional>
#include <string>
#include <vector>

namespace stella {

// The lookup used to evaluate block conditions and result cases over the keywords of one level:
// keyword names give their value (absent -> None), plus the helpers equal_to, exists, is_in,
// is_type, value, and concept type names as strings.
CompiledExpression::Lookup levelLookup(const std::map<std::string, Value>& values, const ConceptTypes& types);

// Evaluates a condition; an error in a catalogue condition is an internal error.
bool evaluateCondition(const CompiledExpression& condition, const CompiledExpression::Lookup& lookup);

// The type of the concept `stella check` goes on with after a command it refused: accepted
// wherever a concept is expected, so that one error does not cause others downstream.
inline const std::string kUncheckedConceptType = "?";

ValidatedCall validateCall(const CommandSpec& command, const ConceptTypes& types, const CallArguments& args);

// Edit distance used for "did you mean" suggestions.
std::size_t editDistance(const std::string& a, const std::string& b);

} // namespace stella
