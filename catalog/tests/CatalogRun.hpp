#pragma once
// Test support for the built-in catalogue: runs a command-file snippet through the Interpreter
// with a handler that validates every call against Catalog::builtin() (as `stella check` does),
// after a prelude that makes the usual concepts (mesh, model, material, load, lists).
#include "catalog/Catalog.hpp"
#include "catalog/CommandSpec.hpp"

#include "interpreter/Interpreter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace stella::catalog_test {

class ValidatingHandler : public CommandHandler {
public:
  std::vector<std::pair<std::string, ValidatedCall>> calls;
  Value callCommand(const std::string& command, const CallArguments& args,
                    const std::string& target) override {
    ValidatedCall v = Catalog::builtin().validate(command, args);
    std::string type = v.resultType;
    calls.emplace_back(command, v);
    if (command == "FIN") {
      finished_ = true;
    }
    if (v.reused) {
      return Value(v.reused);
    }
    if (type.empty()) {
      return Value();
    }
    auto c = std::make_shared<Concept>();
    c->name = target;
    c->type = type;
    return Value(c);
  }
  Value conceptAttribute(const std::shared_ptr<Concept>&, const std::string& name,
                         const SourceLocation& at) override {
    throw UserError(Diagnostic::fatal("TEST", "no attribute " + name, at));
  }
  bool finished() const override { return finished_; }

private:
  bool finished_ = false;
};

class Sink : public DiagnosticSink {
public:
  std::vector<Diagnostic> all;
  void report(const Diagnostic& d) override { all.push_back(d); }
  std::vector<std::string> ids() const {
    std::vector<std::string> out;
    for (const auto& d : all) {
      if (d.severity == Severity::Fatal) {
        out.push_back(d.id);
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  std::string text() const {
    std::string out;
    for (const auto& d : all) {
      out += formatDiagnostic(d) + "\n";
    }
    return out;
  }
};

// Concepts every snippet can use, made by real calls so that they have catalogue types.
inline const char* kPrelude = R"(
MAIL = LIRE_MAILLAGE(UNITE=20, FORMAT='MED')
MO = AFFE_MODELE(MAILLAGE=MAIL, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))
ACIER = DEFI_MATERIAU(ELAS=_F(E=2.0e11, NU=0.3))
MAT = AFFE_MATERIAU(MAILLAGE=MAIL, AFFE=_F(TOUT='OUI', MATER=ACIER))
LOAD = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=_F(GROUP_MA='Bas', DY=0.0), PRES_REP=_F(GROUP_MA='Haut', PRES=25.0))
L1 = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=4))
TIMES = DEFI_LIST_INST(DEFI_LIST=_F(LIST_INST=L1))
RAMPE = DEFI_FONCTION(NOM_PARA='INST', VALE=(0.0, 0.0, 1.0, 1.0))
)";

struct RunResult {
  Sink sink;
  ValidatingHandler handler;
  RunStatus status = RunStatus::Completed;
  // The last validated call (the snippet's subject).
  const ValidatedCall& last() const { return handler.calls.back().second; }
};

inline std::unique_ptr<RunResult> run(const std::string& snippet) {
  auto r = std::make_unique<RunResult>();
  Interpreter interp(r->handler, r->sink);
  for (const auto& name : Catalog::builtin().commandNames()) {
    interp.defineCommand(name);
  }
  r->status = interp.run(SourceFile::fromText("test.comm", std::string(kPrelude) + snippet));
  return r;
}

inline ::testing::AssertionResult valid(const RunResult& r) {
  if (r.status == RunStatus::Completed || r.status == RunStatus::Finished) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << r.sink.text();
}

inline const KeywordTree& zone(const ValidatedCall& v) {
  return v.keywords.occurrences("ZONE").at(0);
}

} // namespace stella::catalog_test
