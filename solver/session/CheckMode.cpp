// `stella check` in the session (issue 15): every command's errors in one pass, and the
// operators that only define data run, so that what a run checks before computing is checked.

#include "Session.hpp"

#include "catalog/Catalog.hpp"
#include "catalog/CommandSpec.hpp"
#include "catalog/KeywordTree.hpp"
#include "catalog/Validator.hpp"

#include <filesystem>
#include <set>

namespace stella {

namespace {

// Operators that compute values of the language only: they run in `stella check` so that a
// formula's syntax is checked and F(x) or a list can be used later in the file.
bool definesLanguageValues(const std::string& command) {
  return command == "FIN" || command == "FORMULE" || command == "DEFI_FONCTION" ||
         command == "DEFI_CONSTANTE" || command == "DEFI_LIST_REEL";
}

// Operators that define data without computing (no solve, no file written): they run in
// `stella check` when every concept they read holds data (their mesh was read from a unit the
// check was given), so their checks are made: groups in the mesh, materials, loads, lists of
// instants, contact zones.
bool definesData(const std::string& command) {
  static const std::set<std::string> names{"LIRE_MAILLAGE",  "DEFI_GROUP",     "MODI_MAILLAGE",
                                           "CREA_MAILLAGE",  "AFFE_MODELE",    "DEFI_MATERIAU",
                                           "AFFE_MATERIAU",  "AFFE_CARA_ELEM", "AFFE_CHAR_MECA",
                                           "AFFE_CHAR_CINE", "DEFI_CONTACT",   "DEFI_LIST_INST"};
  return names.count(command) != 0;
}

// Whether every concept the call reads holds data (a concept `stella check` did not make holds
// none).
bool conceptsHoldData(const KeywordTree& tree) {
  for (const SimpleKeyword& k : tree.simples()) {
    for (const Value& v : k.values) {
      if (v.isConcept() && v.asConcept()->data == nullptr) {
        return false;
      }
    }
  }
  for (const FactorKeyword& f : tree.factors()) {
    for (const KeywordTree& occ : f.occurrences) {
      if (!conceptsHoldData(occ)) {
        return false;
      }
    }
  }
  return true;
}

// Operators that read and check all their inputs, then return a concept without data before
// computing when the session does not execute operators (`stella check`).
bool checksItsInputs(const std::string& command) {
  return command == "STAT_NON_LINE";
}

} // namespace

bool Session::runsInCheck(const std::string& command, const KeywordTree& keywords) const {
  if (definesLanguageValues(command)) {
    return true;
  }
  if (!(definesData(command) || checksItsInputs(command)) || !conceptsHoldData(keywords)) {
    return false;
  }
  if (command == "LIRE_MAILLAGE") {
    const auto unit = units_.find(static_cast<int>(keywords.integer("UNITE")));
    return unit != units_.end() && std::filesystem::exists(unit->second);
  }
  return true;
}

Value Session::callCommand(const std::string& command, const CallArguments& args, const std::string& target) {
  if (options_.executeOperators || checkSink_ == nullptr) {
    return callCommandOnce(command, args, target);
  }
  try {
    return callCommandOnce(command, args, target);
  } catch (const UserError& e) {
    if (e.first().kind == FailureKind::Interrupted) {
      throw;
    }
    for (const Diagnostic& d : e.diagnostics()) {
      checkSink_->report(d);
    }
    return checkPlaceholder(command, args, target);
  }
}

// What the file goes on with after a command `stella check` refused: the reused concept, or a
// concept without data whose type the catalogue accepts wherever a concept is expected.
Value Session::checkPlaceholder(const std::string& command, const CallArguments& args,
                                const std::string& target) {
  for (const KeywordArgument& k : args.keywords) {
    if (k.name == "reuse" && k.value && k.value->isConcept()) {
      return *k.value;
    }
  }
  const CommandSpec* spec = catalog_.find(command);
  if (spec == nullptr || !spec->returnsConcept()) {
    return Value();
  }
  auto c = std::make_shared<Concept>();
  c->name = target;
  c->type = kUncheckedConceptType;
  c->definedAt = args.callLocation;
  if (!target.empty()) {
    concepts_.put(target, c);
  }
  return Value(c);
}

} // namespace stella
