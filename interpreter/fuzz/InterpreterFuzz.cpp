// libFuzzer target: any byte string goes through the lexer (token dump), the parser, the
// pretty-printer (whose output must re-parse to the same tree), the evaluator with a handler
// that accepts every command, and the formula compilers. Crashes, sanitizer reports, internal
// errors and round-trip mismatches are findings.
#include "interpreter/Formatter.hpp"
#include "interpreter/Interpreter.hpp"
#include "interpreter/Parser.hpp"
#include "interpreter/tests/FakeHandler.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace stella;

namespace {

void checkRoundTrip(const std::shared_ptr<const SourceFile>& file) {
  ParseResult first = parseFile(file, true);
  if (!first.errors.empty()) {
    return;
  }
  std::string printed = formatModule(*first.module, first.comments);
  ParseResult second = parseFile(SourceFile::fromText("formatted.comm", printed));
  if (!second.errors.empty() || dumpModule(*first.module, false) != dumpModule(*second.module, false)) {
    std::fprintf(stderr, "round trip failed; formatted text:\n%s\n", printed.c_str());
    for (const auto& d : second.errors) {
      std::fprintf(stderr, "%s", formatDiagnostic(d).c_str());
    }
    std::abort();
  }
}

void run(const std::shared_ptr<const SourceFile>& file) {
  testing::RecordingSink sink;
  testing::FakeHandler handler(false);
  InterpreterOptions options;
  options.whileIterationCap = 100;
  options.operationBudget = 1000;
  options.maxSequenceLength = 1000;
  options.maxStringLength = 10000;
  Interpreter interpreter(handler, sink, options);
  for (const auto& name : testing::fakeCommandNames()) {
    interpreter.defineCommand(name);
  }
  interpreter.run(file);
  for (const auto& d : sink.diagnostics) {
    (void)formatDiagnostic(d);
    if (d.id == "INTERNAL") {
      std::fprintf(stderr, "%s", formatDiagnostic(d).c_str());
      std::abort();
    }
  }
}

void formulas(const std::string& text) {
  try {
    auto e = CompiledExpression::compile(text);
    (void)e.evaluate([](const std::string& name) -> std::optional<Value> {
      return name.size() == 1 ? std::optional<Value>(Value(1.5)) : std::nullopt;
    });
  } catch (const UserError&) {
  }
  try {
    RealFormula f(text, {"X", "Y"}, {{"A", 2.0}});
    double values[] = {0.5, -1.0};
    (void)f(values);
  } catch (const UserError&) {
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  auto file = SourceFile::fromText("fuzz.comm", text);
  (void)dumpTokens(file);
  checkRoundTrip(file);
  run(file);
  if (size < 512) {
    formulas(text);
  }
  return 0;
}
