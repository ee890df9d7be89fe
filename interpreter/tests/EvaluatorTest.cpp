// Evaluator through the Interpreter: command calls and their targets, concepts, FIN handling,
// diagnostics with locations and suggestions, sharing globals across files, limits.
#include "FakeHandler.hpp"
#include "interpreter/Interpreter.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

using testing::FakeHandler;
using testing::RecordingSink;

struct StudyRun {
  RecordingSink sink;
  FakeHandler handler;
  std::unique_ptr<Interpreter> interpreter;
  RunStatus status = RunStatus::Completed;

  explicit StudyRun(const std::string& text, InterpreterOptions options = {}) {
    interpreter = std::make_unique<Interpreter>(handler, sink, options);
    for (const auto& n : testing::fakeCommandNames()) {
      interpreter->defineCommand(n);
    }
    status = interpreter->run(SourceFile::fromText("study.comm", text));
  }
  const Diagnostic* first(Severity s) const {
    for (const auto& d : sink.diagnostics) {
      if (d.severity == s) {
        return &d;
      }
    }
    return nullptr;
  }
};

TEST(Evaluator, KeywordArgumentsCarryLocationsAndValues) {
  StudyRun r("MAIL = LIRE_MAILLAGE(UNITE=20,\n                     FORMAT='MED')\nFIN()\n");
  ASSERT_EQ(r.status, RunStatus::Finished);
  ASSERT_EQ(r.handler.calls.size(), 2u);
  const auto& call = r.handler.calls[0];
  EXPECT_EQ(call.command, "LIRE_MAILLAGE");
  EXPECT_EQ(call.target, "MAIL");
  const KeywordArgument* format = call.args.find("FORMAT");
  ASSERT_NE(format, nullptr);
  EXPECT_EQ(format->value->asString(), "MED");
  EXPECT_EQ(format->location.line, 2);
  EXPECT_EQ(format->location.column, 22);
  EXPECT_EQ(format->valueLocation.column, 29);
  EXPECT_EQ(call.args.callLocation.column, 8);
  auto mail = r.interpreter->global("MAIL");
  ASSERT_TRUE(mail && mail->isConcept());
  EXPECT_EQ(mail->asConcept()->type, "maillage");
}

TEST(Evaluator, FactorKeywordsKeepEachKeywordsLocation) {
  StudyRun r("CH = AFFE_CHAR_MECA(DDL_IMPO=(_F(GROUP_MA='A', DX=0.0),\n                              "
             "_F(GROUP_MA='B', DY=0.0)))\nFIN()\n");
  const KeywordArgument* ddl = r.handler.calls[0].args.find("DDL_IMPO");
  ASSERT_NE(ddl, nullptr);
  ASSERT_TRUE(ddl->value->isTuple());
  const auto& second = ddl->value->items()[1].asFactor();
  EXPECT_EQ(second->location.line, 2);
  EXPECT_EQ(second->keywords[1].name, "DY");
  EXPECT_EQ(second->keywords[1].location.line, 2);
  EXPECT_EQ(second->keywords[1].location.column, 48);
}

TEST(Evaluator, IndexedTargetIsEvaluated) {
  StudyRun r("RES = [None] * 3\nk = 1\nRES[k + 1] = STAT_NON_LINE()\nFIN()\n");
  ASSERT_EQ(r.handler.calls.size(), 2u);
  EXPECT_EQ(r.handler.calls[0].target, "RES[2]");
  auto res = r.interpreter->global("RES");
  ASSERT_TRUE(res && res->isList());
  EXPECT_TRUE(res->items()[2].isConcept());
}

TEST(Evaluator, CallNotWholeRightHandSideHasNoTarget) {
  StudyRun r("x = [STAT_NON_LINE()]\nSTAT_NON_LINE()\nFIN()\n");
  EXPECT_EQ(r.handler.calls[0].target, "");
  EXPECT_EQ(r.handler.calls[1].target, "");
}

TEST(Evaluator, UnknownNameSuggestsTheNearestAndPointsAtIt) {
  StudyRun r("MAILLAGE = LIRE_MAILLAGE()\nMO = AFFE_MODELE(MAILLAGE=MAILAGE)\n");
  ASSERT_EQ(r.status, RunStatus::Failed);
  const Diagnostic* d = r.first(Severity::Fatal);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->id, "LANG_NAME");
  EXPECT_EQ(d->location.line, 2);
  EXPECT_EQ(d->location.column, 27);
  EXPECT_EQ(d->location.length, 7);
  ASSERT_EQ(d->notes.size(), 1u);
  EXPECT_EQ(d->notes[0], "did you mean 'MAILLAGE'?");
  std::string text = formatDiagnostic(*d);
  EXPECT_NE(text.find("study.comm:2:27: error: name 'MAILAGE' is not defined [LANG_NAME]"), std::string::npos)
      << text;
  EXPECT_NE(text.find("                              ^~~~~~~"), std::string::npos) << text;
}

TEST(Evaluator, FinStopsTheRunAndIgnoresTheRest) {
  StudyRun r("DEBUT()\nFIN()\nSTAT_NON_LINE()\n");
  EXPECT_EQ(r.status, RunStatus::Finished);
  EXPECT_EQ(r.handler.calls.size(), 2u);
  StudyRun inLoop("for i in range(5):\n    if i == 2:\n        FIN()\n    print(i)\n");
  EXPECT_EQ(inLoop.status, RunStatus::Finished);
  EXPECT_EQ(inLoop.sink.printed(), (std::vector<std::string>{"0", "1"}));
}

TEST(Evaluator, SyntaxErrorsBeforeFinStopEverything) {
  StudyRun r("DEBUT()\nx = (\nFIN()\n");
  EXPECT_EQ(r.status, RunStatus::SyntaxError);
  EXPECT_TRUE(r.handler.calls.empty());
}

TEST(Evaluator, MissingFinIsAnAlarm) {
  StudyRun r("DEBUT()\n");
  EXPECT_EQ(r.status, RunStatus::Completed);
  const Diagnostic* a = r.first(Severity::Alarm);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->id, "LANG_FIN");
}

TEST(Evaluator, HandlerErrorsAreReportedWithAllTheirDiagnostics) {
  struct Refusing : FakeHandler {
    Value callCommand(const std::string&, const CallArguments& args, const std::string&) override {
      std::vector<Diagnostic> ds;
      for (const auto& kw : args.keywords) {
        ds.push_back(Diagnostic::syntax("CATALOG_1", "unknown keyword " + kw.name, kw.location));
      }
      throw UserError(ds);
    }
  } handler;
  RecordingSink sink;
  Interpreter in(handler, sink);
  in.defineCommand("CMD");
  EXPECT_EQ(in.run(SourceFile::fromText("c.comm", "CMD(A=1, B=2)\n")), RunStatus::Failed);
  ASSERT_EQ(sink.ids(Severity::Fatal), (std::vector<std::string>{"CATALOG_1", "CATALOG_1"}));
  EXPECT_EQ(sink.diagnostics[1].location.column, 10);
}

TEST(Evaluator, GlobalsAreSharedBetweenFiles) {
  RecordingSink sink;
  FakeHandler handler;
  Interpreter in(handler, sink);
  in.defineCommand("LIRE_MAILLAGE");
  in.run(SourceFile::fromText("a.comm", "def twice(x):\n    return 2 * x\nMAIL = LIRE_MAILLAGE()\n"));
  in.run(SourceFile::fromText("b.comm", "print(twice(21), MAIL)\n"));
  EXPECT_EQ(sink.printed(), (std::vector<std::string>{"42 MAIL"}));
}

TEST(Evaluator, NativeFunctionsGetTheCallLocationForTheirErrors) {
  RecordingSink sink;
  FakeHandler handler;
  Interpreter in(handler, sink);
  in.defineNative("CHECK", [](const CallArguments&) -> Value {
    throw UserError(Diagnostic::fatal("NATIVE_1", "refused"));
  });
  in.defineGlobal("E", Value(2.1e5));
  EXPECT_EQ(in.run(SourceFile::fromText("n.comm", "x = E\nCHECK(x)\n")), RunStatus::Failed);
  const Diagnostic& d = sink.diagnostics.back();
  EXPECT_EQ(d.id, "NATIVE_1");
  EXPECT_EQ(d.location.line, 2);
  EXPECT_EQ(d.location.column, 1);
}

TEST(Evaluator, WhileCapReportsWhereItStopped) {
  InterpreterOptions options;
  options.whileIterationCap = 1000;
  StudyRun r("i = 0\nwhile i >= 0:\n    i += 1\n", options);
  ASSERT_EQ(r.status, RunStatus::Failed);
  const Diagnostic* d = r.first(Severity::Fatal);
  EXPECT_EQ(d->id, "LANG_WHILE");
  EXPECT_EQ(d->location.line, 2);
  EXPECT_NE(d->message.find("1000 iterations"), std::string::npos);
  EXPECT_NE(d->message.find("'i >= 0'"), std::string::npos);
}

TEST(Evaluator, SizeLimitsAreEnforced) {
  StudyRun r("x = [0] * 100000000\n");
  ASSERT_NE(r.first(Severity::Fatal), nullptr);
  EXPECT_EQ(r.first(Severity::Fatal)->id, "LANG_SIZE");
  InterpreterOptions options;
  options.operationBudget = 1000;
  StudyRun budget("for i in range(100000):\n    pass\n", options);
  EXPECT_EQ(budget.first(Severity::Fatal)->id, "LANG_BUDGET");
}

TEST(Evaluator, DeepRecursionThroughExpressionsIsCaught) {
  StudyRun r("def f(n):\n    return [f(n + 1)]\nf(0)\n");
  ASSERT_NE(r.first(Severity::Fatal), nullptr);
  EXPECT_EQ(r.first(Severity::Fatal)->id, "LANG_DEPTH");
}

TEST(Evaluator, PrintIsAnInfoWithIdPrint) {
  StudyRun r("print('a', 1)\nFIN()\n");
  ASSERT_EQ(r.sink.diagnostics.size(), 1u);
  EXPECT_EQ(r.sink.diagnostics[0].severity, Severity::Info);
  EXPECT_EQ(r.sink.diagnostics[0].id, "PRINT");
  EXPECT_EQ(r.sink.diagnostics[0].message, "a 1");
}

TEST(Evaluator, RangeLoopsAreLazy) {
  StudyRun r("n = 0\nfor i in range(10**12):\n    n += 1\n    if n == 3:\n        break\nprint(n, "
             "len(range(10**12)))\nFIN()\n");
  EXPECT_EQ(r.sink.printed(), (std::vector<std::string>{"3 1000000000000"}));
}

} // namespace
} // namespace stella
