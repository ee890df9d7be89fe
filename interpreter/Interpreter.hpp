#pragma once
// The entry points of the command language (DESIGN §5). A command file is lexed, parsed into
// an AST, and evaluated statement by statement; command calls go to the CommandHandler.

#include "CommandHandler.hpp"
#include "Diagnostics.hpp"
#include "Value.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stella {

struct InterpreterOptions {
  long whileIterationCap = 10'000'000;       // a `while` that runs longer stops with an error
  long long operationBudget = 1'000'000'000; // operations evaluated (0: unlimited); LANG_BUDGET beyond
  std::int64_t memoryBudget = 0; // bytes the language's values may hold (0: 2 GiB, at most half the RAM)
  std::int64_t maxSequenceLength = 10'000'000; // a longer list/tuple is refused (LANG_SIZE)
  std::int64_t maxStringLength = 100'000'000;  // a longer string is refused (LANG_SIZE)
};

// How a run of a command file ended.
enum class RunStatus {
  Completed,   // reached the end of the file (no FIN(): an alarm has been reported)
  Finished,    // FIN() executed; the rest of the file was ignored
  SyntaxError, // the file did not parse; every syntax error was reported, nothing executed
  Failed       // a runtime or command error stopped the run; it was reported
};

class Interpreter {
public:
  Interpreter(CommandHandler& handler, DiagnosticSink& sink, InterpreterOptions options = {});
  ~Interpreter();
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  // Binds a command name (from the catalogue) in the global scope; calling it goes to the
  // handler.
  void defineCommand(const std::string& name);
  // Binds a global value or a native function.
  void defineGlobal(const std::string& name, Value value);
  void defineNative(const std::string& name, NativeFunction fn);
  // A global's value, if bound.
  std::optional<Value> global(const std::string& name) const;

  // Parses then runs a whole command file in the current global scope (several files run in
  // one session share their globals, like code_aster's POURSUITE). User errors are reported to
  // the sink, never thrown.
  RunStatus run(const std::shared_ptr<const SourceFile>& file);

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Parses only; reports every syntax error of the file to the sink (the parser resynchronises at
// the next statement). Returns true when the file parsed without error.
bool checkSyntax(const std::shared_ptr<const SourceFile>& file, DiagnosticSink& sink);

// Developer views (`stella check --dump-tokens / --dump-ast`, `stella fmt`).
std::string dumpTokens(const std::shared_ptr<const SourceFile>& file);
std::string dumpAst(const std::shared_ptr<const SourceFile>& file);
// Pretty-prints a command file, keeping its comments; the output re-parses to the same AST.
// Throws UserError (all syntax errors) when the file does not parse.
std::string formatSource(const std::shared_ptr<const SourceFile>& file);

// An expression compiled once and evaluated many times: FORMULE bodies, catalogue block
// conditions. Names are resolved at evaluation time through `lookup`; math functions and
// constants (sqrt, cos, pi...) are always available.
class CompiledExpression {
public:
  // Throws UserError (with the position inside the string, mapped onto `origin` when the
  // string literal's location is known) when the text is not a valid expression.
  static CompiledExpression compile(const std::string& text, const SourceLocation& origin = {});
  ~CompiledExpression();
  CompiledExpression(CompiledExpression&&) noexcept;
  CompiledExpression& operator=(CompiledExpression&&) noexcept;

  using Lookup = std::function<std::optional<Value>(const std::string& name)>;
  Value evaluate(const Lookup& lookup) const;
  // The names the expression reads (excluding math built-ins).
  std::vector<std::string> freeNames() const;
  const std::string& text() const;

private:
  CompiledExpression();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A real-valued formula of named real parameters, compiled to a fast form: FORMULE(VALE=...,
// NOM_PARA=(...), constant=value...). Evaluated per node and per time step by operators.
class RealFormula {
public:
  // `constants` are the extra keyword arguments of FORMULE (numbers only).
  RealFormula(const std::string& text, std::vector<std::string> parameters,
              std::vector<std::pair<std::string, double>> constants, const SourceLocation& origin = {});
  ~RealFormula();
  RealFormula(RealFormula&&) noexcept;
  RealFormula& operator=(RealFormula&&) noexcept;

  const std::vector<std::string>& parameters() const;
  // `values[i]` is the value of parameters()[i]. Throws UserError on a domain error
  // (division by zero, sqrt of a negative number), naming the formula and the values.
  double operator()(std::span<const double> values) const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace stella
