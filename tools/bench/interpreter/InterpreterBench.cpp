// Benchmarks of the command language: a generated 10 MB command file (commands with factor
// keywords, loops over lists of concepts, arithmetic, comprehensions) lexed, parsed, and run
// with a handler that executes nothing; and RealFormula evaluated as operators do per node.
#include "interpreter/Interpreter.hpp"
#include "interpreter/Lexer.hpp"
#include "interpreter/Parser.hpp"

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <vector>

using namespace stella;

namespace {

// Returns None for every command: measures the language, not the operators.
class NoOpHandler : public CommandHandler {
public:
  Value callCommand(const std::string&, const CallArguments& args, const std::string&) override {
    calls += 1 + static_cast<long>(args.keywords.size());
    return Value();
  }
  Value conceptAttribute(const std::shared_ptr<Concept>&, const std::string&,
                         const SourceLocation&) override {
    return Value();
  }
  bool finished() const override { return false; }
  long calls = 0;
};

class NullSink : public DiagnosticSink {
public:
  void report(const Diagnostic&) override {}
};

const char* commandNames[] = {"DEBUT",          "FIN",           "LIRE_MAILLAGE", "AFFE_MODELE",
                              "AFFE_CHAR_MECA", "DEFI_MATERIAU", "AFFE_MATERIAU", "STAT_NON_LINE",
                              "TEST_RESU",      "DEFI_LIST_REEL"};

// About 10 MB of study-like text.
const std::string& generatedStudy() {
  static const std::string text = [] {
    std::string s = "DEBUT()\nL_INST = DEFI_LIST_REEL(DEBUT=0.0, INTERVALLE=_F(JUSQU_A=1.0, NOMBRE=10))\n";
    for (int i = 0; s.size() < 10'000'000; ++i) {
      s += fmt::format(
          "MAIL_{0} = LIRE_MAILLAGE(UNITE=20, FORMAT='MED')\n"
          "MO_{0} = AFFE_MODELE(MAILLAGE=MAIL_{0},\n"
          "                     AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='D_PLAN'))\n"
          "MAT_{0} = DEFI_MATERIAU(ELAS=_F(E=2.1e5 * (1.0 + 0.01 * {0}), NU=0.3, RHO=7.8e-9))\n"
          "CH_{0} = AFFE_CHAR_MECA(MODELE=MO_{0},\n"
          "                        DDL_IMPO=(_F(GROUP_MA='Bottom', DX=0.0, DY=0.0), _F(GROUP_MA='Left', "
          "DX=0.0)),\n"
          "                        PRES_REP=_F(GROUP_MA='Top', PRES=1.0e3 * {0} + 2.5 ** 2 - 1.0 / 3.0))\n"
          "RES = [None] * 3\n"
          "for k in range(3):\n"
          "    if k == 0:\n"
          "        algo = 'LAC'\n"
          "    elif k == 1:\n"
          "        algo = 'PENALISATION'\n"
          "    else:\n"
          "        algo = 'CONTRAINTE'\n"
          "    RES[k] = STAT_NON_LINE(MODELE=MO_{0}, EXCIT=_F(CHARGE=CH_{0}), "
          "INCREMENT=_F(LIST_INST=L_INST),\n"
          "                           CONTACT=_F(ALGO_CONT=algo), NEWTON=_F(REAC_ITER=k + 1),\n"
          "                           CONVERGENCE=_F(RESI_GLOB_RELA=1.e-6 * (k + 1), ITER_GLOB_MAXI=20))\n"
          "x_{0} = sum([v * 0.5 for v in range(8)]) + {0} % 7 - len(RES)\n"
          "TEST_RESU(RESU=_F(RESULTAT=RES[2], INST=1.0, NOM_CHAM='DEPL', NOM_CMP='DY', VALE_CALC=-x_{0}))\n",
          i);
    }
    return s + "FIN()\n";
  }();
  return text;
}

void BM_Lex10MB(benchmark::State& state) {
  auto file = SourceFile::fromText("bench.comm", generatedStudy());
  for (auto _ : state) {
    Lexer lexer(file);
    long n = 0;
    while (lexer.next().kind != TokenKind::EndOfFile) {
      ++n;
    }
    benchmark::DoNotOptimize(n);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(generatedStudy().size()));
}

void BM_Parse10MB(benchmark::State& state) {
  auto file = SourceFile::fromText("bench.comm", generatedStudy());
  for (auto _ : state) {
    ParseResult r = parseFile(file);
    benchmark::DoNotOptimize(r.module->body.size());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(generatedStudy().size()));
}

void BM_ParseAndEvaluate10MB(benchmark::State& state) {
  auto file = SourceFile::fromText("bench.comm", generatedStudy());
  long calls = 0;
  for (auto _ : state) {
    NoOpHandler handler;
    NullSink sink;
    Interpreter interpreter(handler, sink);
    for (const char* name : commandNames) {
      interpreter.defineCommand(name);
    }
    RunStatus status = interpreter.run(file);
    if (status != RunStatus::Completed) {
      state.SkipWithError("the generated study did not run");
    }
    calls = handler.calls;
  }
  state.counters["calls+keywords"] = static_cast<double>(calls);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(generatedStudy().size()));
}

// One FORMULE evaluation as an operator does it per node and per step.
void BM_RealFormula(benchmark::State& state) {
  RealFormula f("A * sin(X) * exp(-Y / 2.) + X**2 - 3. * Y + (1. if X > 0 else 0.)", {"X", "Y"},
                {{"A", 2.0}});
  std::vector<double> xs(1024);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    xs[i] = std::sin(static_cast<double>(i));
  }
  double sum = 0.0;
  for (auto _ : state) {
    for (double x : xs) {
      double values[] = {x, 0.5 * x};
      sum += f(values);
    }
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(xs.size()));
}

// The same formula written directly in C++, as the lower bound.
void BM_RealFormulaNative(benchmark::State& state) {
  std::vector<double> xs(1024);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    xs[i] = std::sin(static_cast<double>(i));
  }
  double sum = 0.0;
  for (auto _ : state) {
    for (double x : xs) {
      double y = 0.5 * x;
      benchmark::DoNotOptimize(y);
      sum += 2.0 * std::sin(x) * std::exp(-y / 2.) + x * x - 3. * y + (x > 0 ? 1. : 0.);
    }
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(xs.size()));
}

void BM_CompiledExpressionCondition(benchmark::State& state) {
  auto e = CompiledExpression::compile("FORMULATION == 'CONTINUE' and ALGO_CONT in ('LAC', 'STANDARD')");
  auto lookup = [](const std::string& n) -> std::optional<Value> {
    if (n == "FORMULATION") {
      return Value("CONTINUE");
    }
    return Value("LAC");
  };
  for (auto _ : state) {
    benchmark::DoNotOptimize(e.evaluate(lookup).truthy());
  }
}

} // namespace

BENCHMARK(BM_Lex10MB)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Parse10MB)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseAndEvaluate10MB)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RealFormula);
BENCHMARK(BM_RealFormulaNative);
BENCHMARK(BM_CompiledExpressionCondition);

BENCHMARK_MAIN();
