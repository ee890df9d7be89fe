#pragma once
// Private to the catalogue: the validator of one command call (Validator.hpp's validateCall),
// split by what it checks: CallValidator.cpp walks the levels (active blocks, defaults, reuse,
// result type), CallValidatorValues.cpp checks the values of simple keywords,
// CallValidatorKeywords.cpp factor keywords, rules and the keywords refused.

#include "Validator.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace stella::validation {

std::string joinNames(const std::vector<std::string>& names, const std::string& sep = ", ");

std::string joinValues(const ValueList& values);

// A value as seen by block conditions: one value stays a scalar, several are a tuple.
Value conditionValue(const ValueList& values);

// The keywords a level offers under the current values: active definitions in order, and the
// rules of the level and of its active blocks.
struct ActiveSet {
  std::vector<const Entry*> order;
  std::map<std::string, const Entry*> byName;
  std::vector<const Rule*> rules;
};

class CallValidator {
public:
  CallValidator(const CommandSpec& command, const ConceptTypes& types) : command_(command), types_(types) {}
  ValidatedCall run(const CallArguments& args);

private:
  const CommandSpec& command_;
  const ConceptTypes& types_;
  std::vector<Diagnostic> errors_;
  std::vector<std::vector<std::pair<const FactorSpec*, std::string>>> variants_; // per factor being validated

  // Records catalogue entry `key` (messages/catalog.msg) with `args`, then the computed `notes`.
  void error(std::string_view key, msg::Args args, const SourceLocation& at,
             std::vector<std::string> notes = {});

  void checkReuse(const KeywordArgument* reuse, ValidatedCall& out, const SourceLocation& call);

  std::string resultType(const KeywordTree& tree);

  ActiveSet collectActive(const Level& level, const CompiledExpression::Lookup& lookup);

  void addActive(const Level& level, const CompiledExpression::Lookup& lookup, ActiveSet& a);

  // Fixed point of "block conditions read keyword values, active blocks bring defaults".
  ActiveSet settle(const Level& level, const std::map<std::string, Value>& given,
                   std::map<std::string, Value>& env, std::map<std::string, Value>& ruleDefaults);

  KeywordTree validateLevel(const Level& level, const std::vector<KeywordArgument>& written,
                            const SourceLocation& at, const std::string& where);

  // Records CATALOG_17 (entry `key`: CATALOG_17.keyword or .value) with `args`, then `why` and `notes`.
  void notImplementedYet(std::string_view key, msg::Args args, const std::string& why,
                         const SourceLocation& at, std::vector<std::string> notes = {});

  // A keyword the catalogue marks non_implemente= given by the user: refused unless its value is
  // the one accepted (accepte=, the keyword's default).
  bool refuseNotImplemented(const std::string& name, const SimpleSpec& s, const KeywordArgument& k,
                            const std::string& where);

  static void collectVariants(const Level& level, const std::string& name, const FactorSpec* self,
                              const std::string& condition,
                              std::vector<std::pair<const FactorSpec*, std::string>>& out);

  void reportNotAllowed(const Level& level, const ActiveSet& active, const KeywordArgument& k,
                        const std::string& where, bool quietIfConditional);

  static ValueList items(const Value& v) { return v.isSequence() ? v.items() : ValueList{v}; }

  // A default or rule default, normalised like a user value (ints to reals for 'R').
  static ValueList normalised(const SimpleSpec& s, const Value& v);

  std::string expectedTypes(const SimpleSpec& s);

  // Converts one value to the spec's type; nullopt when it does not fit.
  std::optional<Value> convert(const SimpleSpec& s, const Value& v);

  std::string countText(const SimpleSpec& s);

  std::optional<ValueList> checkSimple(const std::string& name, const SimpleSpec& s, const KeywordArgument& k,
                                       const std::string& where);

  // The keyword arguments of one occurrence given as _F(...) or as a dict.
  std::optional<std::vector<KeywordArgument>> occurrence(const Value& v, const SourceLocation& at,
                                                         SourceLocation& where);

  std::vector<KeywordTree> checkFactor(const std::string& name, const FactorSpec& f, const KeywordArgument& k,
                                       const std::string& where);

  void checkRules(const ActiveSet& active, const std::vector<std::string>& present, const SourceLocation& at,
                  const std::string& where);
};

} // namespace stella::validation
