#pragma once
// A CommandHandler for tests, the fuzzer and the benchmark: records every command call with its
// target, makes a target for each, implements FIN, DETRUIRE, FORMULE (through RealFormula) and a
// few target methods (EXTR_TABLE, LIST_PARA), and collects diagnostics.

#include "interpreter/CommandHandler.hpp"
#include "interpreter/Diagnostics.hpp"
#include "interpreter/Interpreter.hpp"

#include <cctype>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace stella::testing {

// Command names every test file may call.
inline const std::vector<std::string>& fakeCommandNames() {
  static const std::vector<std::string> names = {"DEBUT",          "POURSUITE",      "FIN",
                                                 "LIRE_MAILLAGE",  "AFFE_MODELE",    "DEFI_MATERIAU",
                                                 "AFFE_MATERIAU",  "AFFE_CHAR_MECA", "AFFE_CHAR_CINE",
                                                 "DEFI_CONTACT",   "STAT_NON_LINE",  "MECA_STATIQUE",
                                                 "DEFI_LIST_REEL", "DEFI_LIST_INST", "DEFI_FONCTION",
                                                 "TEST_RESU",      "TEST_TABLE",     "IMPR_RESU",
                                                 "IMPR_TABLE",     "CREA_TABLE",     "POST_RELEVE_T",
                                                 "CALC_CHAMP",     "CALC_TABLE",     "DETRUIRE",
                                                 "FORMULE",        "CREA_MAILLAGE",  "MODI_MAILLAGE",
                                                 "DEFI_GROUP",     "CREA_CHAMP",     "RECU_TABLE",
                                                 "DEFI_CONSTANTE", "CALC_PRESSION",  "IMPR_FONCTION",
                                                 "LIRE_RESU",      "EXTR_RESU"};
  return names;
}

class RecordingSink : public DiagnosticSink {
public:
  void report(const Diagnostic& d) override { diagnostics.push_back(d); }
  std::vector<Diagnostic> diagnostics;

  std::vector<std::string> printed() const {
    std::vector<std::string> out;
    for (const auto& d : diagnostics) {
      if (d.id == "PRINT") {
        out.push_back(d.message);
      }
    }
    return out;
  }
  std::vector<std::string> ids(Severity s) const {
    std::vector<std::string> out;
    for (const auto& d : diagnostics) {
      if (d.severity == s) {
        out.push_back(d.id);
      }
    }
    return out;
  }
};

class FakeHandler : public CommandHandler {
public:
  struct Call {
    std::string command;
    std::string target;
    CallArguments args;
  };

  // When `record` is false the handler keeps nothing (benchmark, fuzzing).
  explicit FakeHandler(bool record = true) : record_(record) {}

  Value callCommand(const std::string& command, const CallArguments& args,
                    const std::string& target) override {
    ++callCount;
    if (record_) {
      calls.push_back(Call{command, target, args});
    }
    if (command == "FIN") {
      finished_ = true;
      return Value();
    }
    if (command == "DETRUIRE") {
      destroy(args);
      return Value();
    }
    if (command == "FORMULE") {
      return formula(args, target);
    }
    if (const KeywordArgument* reuse = args.find("reuse"); reuse != nullptr && reuse->value->isConcept()) {
      return *reuse->value;
    }
    if (command == "DEBUT" || command == "TEST_RESU" || command == "TEST_TABLE" ||
        command.rfind("IMPR_", 0) == 0) {
      return Value();
    }
    auto c = std::make_shared<Concept>();
    c->name = target.empty() ? "_anonymous" : target;
    c->type = typeOf(command);
    c->definedAt = args.callLocation;
    return Value(c);
  }

  Value conceptAttribute(const std::shared_ptr<Concept>& object, const std::string& name,
                         const SourceLocation& at) override {
    if (name == "EXTR_TABLE" && object->type == "table") {
      return makeNativeFunction(name, [](const CallArguments&) -> Value {
        auto d = std::make_shared<DictObject>();
        d->items.emplace_back(Value("INST"), Value::list({Value(0.5), Value(1.0)}));
        d->items.emplace_back(Value("DX"), Value::list({Value(0.1), Value(0.2)}));
        return Value(d);
      });
    }
    if (name == "LIST_PARA") {
      return makeNativeFunction(name, [](const CallArguments&) -> Value {
        auto d = std::make_shared<DictObject>();
        d->items.emplace_back(Value("INST"), Value::list({Value(0.5), Value(1.0)}));
        return Value(d);
      });
    }
    if (name == "getName") {
      std::string n = object->name;
      return makeNativeFunction(name, [n](const CallArguments&) -> Value { return Value(n); });
    }
    if (name == "__call__" && object->type == "formule") {
      auto f = formulas_.at(object.get());
      return makeNativeFunction(object->name, [f](const CallArguments& a) -> Value {
        std::vector<double> values;
        for (const auto& v : a.positional) {
          if (!v.isNumber()) {
            throw UserError(Diagnostic::fatal("FORMULA_ARGS", "a formula takes real numbers"));
          }
          values.push_back(v.asReal());
        }
        return Value((*f)(values));
      });
    }
    throw UserError(Diagnostic::fatal(
        "CONCEPT_ATTR",
        "concept '" + object->name + "' of type " + object->type + " has no attribute '" + name + "'", at));
  }

  bool finished() const override { return finished_; }

  std::vector<Call> calls;
  long callCount = 0;

private:
  static std::string typeOf(const std::string& command) {
    if (command == "LIRE_MAILLAGE" || command == "CREA_MAILLAGE" || command == "MODI_MAILLAGE") {
      return "maillage";
    }
    if (command == "STAT_NON_LINE") {
      return "evol_noli";
    }
    if (command == "CREA_TABLE" || command == "POST_RELEVE_T" || command == "CALC_TABLE" ||
        command == "RECU_TABLE") {
      return "table";
    }
    std::string t = command;
    for (char& c : t) {
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return t;
  }

  void destroy(const CallArguments& args) {
    const KeywordArgument* kw = args.find("CONCEPT");
    if (kw == nullptr) {
      return;
    }
    auto each = [](const Value& v, auto&& f) {
      if (v.isSequence()) {
        for (const auto& item : v.items()) {
          f(item);
        }
      } else {
        f(v);
      }
    };
    each(*kw->value, [&](const Value& occurrence) {
      if (!occurrence.isFactor()) {
        return;
      }
      for (const auto& k : occurrence.asFactor()->keywords) {
        if (k.name == "NOM") {
          each(*k.value, [](const Value& c) {
            if (c.isConcept()) {
              c.asConcept()->destroyed = true;
            }
          });
        }
      }
    });
  }

  Value formula(const CallArguments& args, const std::string& target) {
    const KeywordArgument* vale = args.find("VALE");
    const KeywordArgument* para = args.find("NOM_PARA");
    if (vale == nullptr || !vale->value->isString()) {
      throw UserError(
          Diagnostic::fatal("FORMULA_ARGS", "FORMULE needs VALE='expression'", args.callLocation));
    }
    std::vector<std::string> names;
    if (para != nullptr) {
      if (para->value->isString()) {
        names.push_back(para->value->asString());
      } else if (para->value->isSequence()) {
        for (const auto& v : para->value->items()) {
          names.push_back(v.str());
        }
      }
    }
    std::vector<std::pair<std::string, double>> constants;
    for (const auto& kw : args.keywords) {
      if (kw.name != "VALE" && kw.name != "NOM_PARA" && kw.value->isNumber()) {
        constants.emplace_back(kw.name, kw.value->asReal());
      }
    }
    auto f = std::make_shared<RealFormula>(vale->value->asString(), names, constants, vale->valueLocation);
    auto c = std::make_shared<Concept>();
    c->name = target;
    c->type = "formule";
    formulas_[c.get()] = f;
    keep_.push_back(c);
    return Value(c);
  }

  bool record_;
  bool finished_ = false;
  std::map<const Concept*, std::shared_ptr<RealFormula>> formulas_;
  std::vector<std::shared_ptr<Concept>> keep_;
};

} // namespace stella::testing
