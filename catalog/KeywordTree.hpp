#pragma once
// The typed, complete keyword tree of one validated command call: what an operator reads.
// Built only by the catalogue's validator (defaults filled in active blocks, `statut='d'`
// factor keywords created, scalars and one-element lists normalised to lists, integers
// converted to reals where the catalogue says 'R'). Operators never see unchecked input.

#include "interpreter/SourceFile.hpp"
#include "interpreter/Value.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stella {

class KeywordTree;

// One simple keyword: its values (always a list, even for a scalar), where it was written and
// whether it came from a default.
struct SimpleKeyword {
  std::string name;
  ValueList values;
  SourceLocation location;
  bool defaulted = false;
};

// One factor keyword: its occurrences, each a KeywordTree.
struct FactorKeyword {
  std::string name;
  std::vector<KeywordTree> occurrences;
  SourceLocation location;
  bool defaulted = false; // created from statut='d'
};

class KeywordTree {
public:
  // Construction (validator only).
  void addSimple(SimpleKeyword k);
  void addFactor(FactorKeyword k);
  void setLocation(SourceLocation at) { location_ = std::move(at); }

  const SourceLocation& location() const { return location_; }
  const std::vector<SimpleKeyword>& simples() const { return simples_; }
  const std::vector<FactorKeyword>& factors() const { return factors_; }

  // Whether a simple or factor keyword is present (given or defaulted).
  bool has(const std::string& name) const;
  const SimpleKeyword* simple(const std::string& name) const;
  const FactorKeyword* factor(const std::string& name) const;

  // Typed access. The validator guarantees the types; asking for a keyword that is absent, or
  // with a type the catalogue does not give it, is an internal error (STELLA_ASSERT).
  std::string text(const std::string& name) const;
  double real(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  std::vector<std::string> texts(const std::string& name) const;
  std::vector<double> reals(const std::string& name) const;
  std::vector<std::int64_t> integers(const std::string& name) const;
  std::shared_ptr<Concept> conceptValue(const std::string& name) const;
  std::vector<std::shared_ptr<Concept>> conceptValues(const std::string& name) const;
  const Value& value(const std::string& name) const; // the first value
  // With a fallback when absent.
  std::string textOr(const std::string& name, const std::string& fallback) const;
  double realOr(const std::string& name, double fallback) const;
  std::int64_t integerOr(const std::string& name, std::int64_t fallback) const;

  // Occurrences of a factor keyword (empty when absent).
  const std::vector<KeywordTree>& occurrences(const std::string& name) const;
  // Where a keyword was written (or the tree's location for defaults).
  SourceLocation locationOf(const std::string& name) const;

  // The tree as command-language text with every keyword, defaults included, for the command
  // echo in the message file: `KW=value,` one per line, factor keywords as `_F(...)`.
  std::string format(int indent) const;

private:
  std::vector<SimpleKeyword> simples_;
  std::vector<FactorKeyword> factors_;
  SourceLocation location_;
};

} // namespace stella
