#pragma once
// The model of the keyword catalogue (DESIGN §4): a command (OPER / MACRO / PROC) owns a tree of
// simple keywords (SIMP), factor keywords (FACT) and conditional blocks (BLOC), with rules
// (UN_PARMI, AU_MOINS_UN, EXCLUS, ENSEMBLE, PRESENT_PRESENT, PRESENT_ABSENT, NON_VIDE).
// Specs are immutable once built; a spec may be shared by several parents (catalogue fragments),
// so a keyword's name is held by the parent's entry, not by the spec.

#include "interpreter/Interpreter.hpp"
#include "interpreter/Value.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace stella {

// statut: 'o' mandatory, 'f' optional, 'c' hidden/automatic, 'd' factor created with defaults.
enum class Presence { Mandatory, Optional, Hidden, Defaulted };
char presenceLetter(Presence p);

constexpr int kUnbounded = -1; // max='**'

struct Rule {
  enum class Kind { UnParmi, AuMoinsUn, Exclus, Ensemble, PresentPresent, PresentAbsent, NonVide };
  Kind kind = Kind::UnParmi;
  std::vector<std::string> names;
  // UN_PARMI / AU_MOINS_UN may carry defaults inserted when none of the names is given.
  std::vector<std::pair<std::string, Value>> defaults;

  std::string keyword() const; // "UN_PARMI"
  std::string text() const;    // "UN_PARMI(TOUT, GROUP_MA; default TOUT='OUI')"
  // What the rule demands, in words, for error messages.
  std::string explanation() const;
  // The names involved that `present` violates, empty when the rule holds.
  bool holds(const std::vector<std::string>& present) const;
};

struct Level;
struct SimpleSpec;
struct FactorSpec;
struct BlockSpec;

// One named child of a level: a simple keyword, a factor keyword or a block.
struct Entry {
  std::string name; // keyword name, or the block's name (b_...)
  std::shared_ptr<const SimpleSpec> simple;
  std::shared_ptr<const FactorSpec> factor;
  std::shared_ptr<const BlockSpec> block;
};

// The content of a command, of a factor keyword occurrence or of a block.
struct Level {
  std::vector<Entry> entries; // in definition (display) order
  std::vector<Rule> rules;
  // Keywords of the reference catalogue deliberately left out because they belong to physics
  // outside the project (thermal, XFEM, shells' internal options...): refused by name.
  std::vector<std::string> outOfScope;
  // Keywords not in the catalogue are accepted as given (FORMULE's constants: p0=p0).
  bool freeKeywords = false;
};

struct SimpleSpec {
  Presence presence = Presence::Optional;
  std::vector<std::string> types; // 'TXM', 'R', 'I', 'C', or concept types (several = tuple)
  std::optional<ValueList> defaultValue;
  ValueList into;
  // Values of the reference catalogue outside stella's scope (FORMULATION='XFEM'): refused by
  // name with CATALOG_SCOPE rather than as unknown values.
  ValueList outOfScopeValues;
  int min = 1;
  int max = 1; // kUnbounded for '**'
  std::optional<double> valMin;
  std::optional<double> valMax;
  bool noRepeat = false;
  std::string description;
  // 2020/2025 generations: the keyword is the old spelling of `renamedTo` (stored under that
  // name in the validated tree).
  std::string renamedTo;
  // An older form given as a factor keyword (DEBUT(CODE=_F(...)) in 2020): validated against
  // this factor, then stored as `oldFactorValue`.
  std::shared_ptr<const FactorSpec> oldFactorForm;
  std::optional<Value> oldFactorValue;
  // Support in stella (declared here only): non_implemente='why' refuses the keyword when the user
  // gives it (CATALOG_17 "not implemented yet"), except with the value accepte= (its default);
  // implemente=(...) lists the values of `into` stella implements, the others are refused;
  // stella='...' says what stella does with the keyword (shown in doc/catalog).
  std::optional<std::string> notImplemented;
  std::optional<Value> acceptedValue;
  ValueList implementedValues;
  std::string stellaNote;
  bool isConceptType() const;
};

struct FactorSpec {
  Presence presence = Presence::Optional;
  int min = 1; // occurrences
  int max = 1;
  std::string description;
  std::string renamedTo;
  std::optional<std::string> notImplemented; // non_implemente='why' (see SimpleSpec)
  std::string stellaNote;
  Level body;
};

struct BlockSpec {
  std::string conditionText;
  std::shared_ptr<const CompiledExpression> condition;
  std::string description;
  Level body;
};

enum class CommandKind { Oper, Macro, Proc };

struct CommandSpec {
  std::string name;
  CommandKind kind = CommandKind::Oper;
  std::string description;
  std::string file; // the catalogue file it was read from
  // Result type: a fixed type, or the first condition of `resultCases` that holds, or the type of
  // the concept given at keyword `resultFrom`.
  std::string resultType;
  std::vector<std::pair<std::shared_ptr<const CompiledExpression>, std::string>> resultCases;
  std::vector<std::string> resultFrom;      // the first of these keywords that is given
  char reentrant = 'n';                     // 'n' never, 'o' must reuse, 'f' may reuse
  std::string reuseKeyword;                 // the keyword naming the reused concept ('o:MAILLAGE')
  std::vector<std::string> removedKeywords; // names rules may cite although no longer defined
  // non_implemente='why': stella has no operator for the command yet (COMMAND_1 when called).
  std::optional<std::string> notImplemented;
  Level body;

  bool returnsConcept() const {
    return kind != CommandKind::Proc && (!resultType.empty() || !resultCases.empty() || !resultFrom.empty());
  }
};

// The concept type hierarchy: `isA("evol_noli", "resultat")`.
class ConceptTypes {
public:
  void addParent(const std::string& child, const std::string& parent);
  bool isA(const std::string& type, const std::string& wanted) const;
  bool known(const std::string& type) const;
  void addKnown(const std::string& type) { known_[type]; }

private:
  std::map<std::string, std::vector<std::string>> known_; // type -> parents
};

// Human-readable names for types in messages: 'R' -> "a real".
std::string typeDescription(const std::string& type);

} // namespace stella
