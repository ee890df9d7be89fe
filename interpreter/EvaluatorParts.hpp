#pragma once
// Internal to the evaluator's source files (Evaluator*.cpp): user functions and the guard
// against evaluations nested too deeply. The public interface is Evaluator.hpp.

#include "Evaluator.hpp"

#include <string>

namespace stella {

// A function defined with `def` (or `lambda`) in a command file.
class UserFunction : public Callable {
public:
  UserFunction(std::shared_ptr<const Module> definedIn, const Stmt* definition, const Expr* lambdaExpr,
               ValueList defaultValues)
      : module(std::move(definedIn)), def(definition), lambda(lambdaExpr),
        defaults(std::move(defaultValues)) {}
  std::string name() const override { return def != nullptr ? def->name : "<lambda>"; }
  std::shared_ptr<const Module> module;
  const Stmt* def;
  const Expr* lambda;
  ValueList defaults; // one per parameter; None where there is no default (see hasDefault)
  std::vector<bool> hasDefault;
};

namespace evaluation {

// RAII depth counter: refuses evaluations nested deeper than the stack can hold.
class DepthGuard {
public:
  DepthGuard(int& depth, int max, const Evaluator& ev, const Pos& pos) : depth_(depth) {
    if (++depth_ > max) {
      --depth_;
      ev.raise(pos, "LANG_DEPTH",
               "evaluation nested too deeply (more than " + std::to_string(max) + " levels)",
               "is a function calling itself without end?");
    }
  }
  ~DepthGuard() { --depth_; }
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;

private:
  int& depth_;
};

} // namespace evaluation

} // namespace stella
