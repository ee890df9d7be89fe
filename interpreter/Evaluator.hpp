#pragma once
// The tree-walking evaluator of the command language. Statements run in a global scope shared
// by the files of a session; user functions get a local scope; comprehensions a nested one.
// Errors are UserError located in the command file.

#include "Ast.hpp"
#include "CommandHandler.hpp"
#include "Interpreter.hpp"
#include "Runtime.hpp"
#include "WorkMeter.hpp"

#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace stella {

// Thrown (internally) when FIN() has been executed: the rest of the run is skipped.
struct FinishSignal {};

struct EvaluatorOptions {
  long whileIterationCap = 10'000'000;
  EvaluationBudget budget; // operations and memory (WorkMeter.hpp)
  RuntimeLimits limits;
  int maxCallDepth = 200;
  int maxEvalDepth = 2500;
};

class Evaluator {
public:
  Evaluator(CommandHandler* handler, DiagnosticSink* sink, EvaluatorOptions options);
  // Empties the lists and dicts that (still) contain themselves, directly or not: reference
  // cycles made by the command file (`L.append(L)`) would otherwise never be freed.
  ~Evaluator();
  Evaluator(const Evaluator&) = delete;
  Evaluator& operator=(const Evaluator&) = delete;
  // Records a list or dict changed in place (the only way a cycle can form).
  void noteMutated(const Value& container);

  // Runs the statements of a parsed module (throws UserError, FinishSignal).
  void execModule(const std::shared_ptr<const Module>& module, std::size_t firstStatement = 0);
  // Evaluates one expression of `module` (CompiledExpression), with names first looked up
  // through `lookup` and math functions available by their bare names.
  Value evalStandalone(const std::shared_ptr<const Module>& module, const Expr& expr,
                       const std::function<std::optional<Value>(const std::string&)>* lookup);

  std::unordered_map<std::string, Value>& globals() { return globals_; }
  void defineCommand(const std::string& name);

  // Calls a callable value with evaluated arguments (used by builtins such as sorted(key=...)).
  Value call(const Value& callee, const CallArguments& args, const Pos& at, const std::string& target = {});

  SourceLocation location(const Pos& pos) const {
    return SourceLocation{file_, pos.line, pos.column, pos.length};
  }
  // Throws catalogue entry `key` (messages/language.msg) with `args` at `pos`; `note`, when not
  // empty, is a computed advice (a spelling suggestion) for an entry that has none.
  [[noreturn]] void raise(const Pos& pos, std::string_view key, msg::Args args = {},
                          const std::string& note = {}) const;
  [[noreturn]] void raise(const Pos& pos, const LangError& e) const;

  const EvaluatorOptions& options() const { return options_; }
  DiagnosticSink* sink() const { return sink_; }
  void countStep(const Pos& pos);
  WorkMeter& meter() { return meter_; }

private:
  enum class Flow { Normal, Break, Continue, Return };
  struct Scope {
    std::unordered_map<std::string, Value> vars;
    Scope* parent = nullptr; // comprehension scopes see their enclosing scope
    bool function = false;
    std::unordered_set<std::string> globalNames;
  };
  friend class UserFunction;

  Flow execBlock(const std::vector<StmtPtr>& body);
  Flow execStatement(const Stmt& s);
  Flow execStatementOfKind(const Stmt& s);
  void execAssign(const Stmt& s);
  void execAugAssign(const Stmt& s);
  Flow execFor(const Stmt& s);
  Flow execWhile(const Stmt& s);
  Flow execTry(const Stmt& s);
  Flow handleError(const Stmt& s, const UserError& error);
  [[noreturn]] void execRaise(const Stmt& s);
  void execDel(const Stmt& s);
  void execDef(const Stmt& s);
  void execImport(const Stmt& s);
  void execFromImport(const Stmt& s);

  Value eval(const Expr& e);
  Value evalName(const Expr& e);
  Value evalCall(const Expr& e, const std::string& target = {});
  Value evalMethodCall(const Expr& e, const Value& object);
  Value evalAttribute(const Expr& e);
  Value evalCompare(const Expr& e);
  Value evalListComp(const Expr& e);
  Value evalFString(const Expr& e);
  Value evalDict(const Expr& e);
  Value evalLambda(const Expr& e);
  void collectArguments(const Expr& call, std::size_t first, CallArguments& args);

  void assignTo(const Expr& target, const Value& value);
  void bindName(const std::string& name, const Value& value);
  std::string targetText(const Expr& target, Value* index);

  Value callCommand(const std::string& name, const CallArguments& args, const Pos& at,
                    const std::string& target);
  Value callUser(const class UserFunction& fn, const CallArguments& args, const Pos& at);
  Value callNative(const NativeCallable& fn, const CallArguments& args, const Pos& at);
  Value attributeOf(const Value& object, const std::string& name, const Pos& at);
  void checkNotDestroyed(const Value& v, const Pos& at, int depth = 0) const;

  [[noreturn]] void unknownName(const Expr& e) const;
  std::string runningLoopNote() const;

  // The loops being run, innermost last: a budget error names the innermost one.
  struct RunningLoop {
    const Stmt* statement = nullptr; // a for or while loop
    const Expr* clause = nullptr;    // or the `for` clause of a comprehension
    std::int64_t turns = 0;
  };
  class LoopGuard;
  class MeterGuard;
  std::vector<std::string> visibleNames() const;

  CommandHandler* handler_;
  DiagnosticSink* sink_;
  EvaluatorOptions options_;
  std::shared_ptr<const SourceFile> file_;
  std::shared_ptr<const Module> module_;
  std::unordered_map<std::string, Value> globals_;
  Scope* scope_ = nullptr;
  Value returnValue_;
  int callDepth_ = 0;
  int evalDepth_ = 0;
  WorkMeter meter_;
  std::vector<RunningLoop> loops_;
  const std::function<std::optional<Value>(const std::string&)>* lookup_ = nullptr;
  std::unordered_map<const void*, std::weak_ptr<ListObject>> mutatedLists_;
  std::unordered_map<const void*, std::weak_ptr<DictObject>> mutatedDicts_;
  const void* lastMutated_ = nullptr;
  std::vector<std::exception_ptr> handling_; // errors whose `except` block runs (for a bare `raise`)
};

// Python's built-ins (range, len, print, _F...) and the math module.
class Builtin : public Callable {
public:
  enum class Id {
    Print,
    Range,
    Len,
    Abs,
    Min,
    Max,
    Sum,
    Float,
    Int,
    Str,
    Bool,
    Round,
    Zip,
    Enumerate,
    List,
    Tuple,
    Dict,
    IsInstance,
    Sorted,
    Reversed,
    Any,
    All,
    Repr,
    Factor,
    Pow,
    DivMod,
    Type,
    Map,
    Filter
  };
  Builtin(Id which, std::string name) : id(which), name_(std::move(name)) {}
  std::string name() const override { return name_; }
  Id id;

private:
  std::string name_;
};

// The global names every command file sees (built-ins) and the math module's contents.
const std::unordered_map<std::string, Value>& builtinNames();
const std::unordered_map<std::string, Value>& mathNames();
// The sandboxed `os.path` (join, basename, dirname, split, splitext, isabs, sep): string
// functions only, no access to the file system (OsPath.cpp).
const std::unordered_map<std::string, Value>& osPathNames();
Value callBuiltin(Evaluator& ev, const Builtin& b, const CallArguments& args, const Pos& at);
// str/list/dict/tuple methods: `s.upper()`, `l.append(x)`; nullopt when there is no such method.
std::optional<Value> callMethod(Evaluator& ev, const Value& object, const std::string& name,
                                const CallArguments& args, const Pos& at);
bool hasMethod(const Value& object, const std::string& name);

} // namespace stella
