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

// Makes an evaluator's meter the one built-ins charge while it runs (restores the previous one:
// a command may evaluate expressions with an evaluator of its own).
class Evaluator::MeterGuard {
public:
  explicit MeterGuard(WorkMeter& meter) : previous_(activeWorkMeter()) { setActiveWorkMeter(&meter); }
  ~MeterGuard() { setActiveWorkMeter(previous_); }
  MeterGuard(const MeterGuard&) = delete;
  MeterGuard& operator=(const MeterGuard&) = delete;

private:
  WorkMeter* previous_;
};

// Records a running loop for the budget's message; `turn()` counts one turn.
class Evaluator::LoopGuard {
public:
  LoopGuard(std::vector<RunningLoop>& loops, const Stmt* statement, const Expr* clause) : loops_(loops) {
    loops_.push_back(RunningLoop{statement, clause, 0});
  }
  ~LoopGuard() { loops_.pop_back(); }
  void turn() { ++loops_.back().turns; }
  LoopGuard(const LoopGuard&) = delete;
  LoopGuard& operator=(const LoopGuard&) = delete;

private:
  std::vector<RunningLoop>& loops_;
};

namespace evaluation {

// RAII depth counter: refuses evaluations nested deeper than the stack can hold.
class DepthGuard {
public:
  DepthGuard(int& depth, int max, const Evaluator& ev, const Pos& pos) : depth_(depth) {
    if (++depth_ > max) {
      --depth_;
      ev.raise(pos, "LANG_DEPTH.3", {{"max", std::to_string(max)}});
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
