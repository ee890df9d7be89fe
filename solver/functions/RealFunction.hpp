#pragma once
// Real functions of named real parameters, as concepts: tabulated functions (DEFI_FONCTION,
// type `fonction`) and formulas (FORMULE, type `formule`). Loads use them as multipliers of
// time (FONC_MULT) and as values varying in space.

#include "interpreter/Interpreter.hpp"
#include "interpreter/Value.hpp"

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace stella {

class RealFunction : public ConceptData {
public:
  // The parameter names, e.g. {"INST"} or {"X", "Y"}.
  virtual std::vector<std::string> parameters() const = 0;
  // `values[i]` is the value of parameters()[i]. Throws UserError (FUNCTION_n) naming the
  // function when a value is outside its domain.
  virtual double evaluate(std::span<const double> values) const = 0;
  // The function of one parameter at x.
  double operator()(double x) const { return evaluate(std::span<const double>(&x, 1)); }
  std::string name; // the concept's name, for messages
};

enum class Extension { Excluded, Constant, Linear }; // PROL_GAUCHE / PROL_DROITE

// DEFI_FONCTION: pairs (x, y) with x strictly increasing, linear (or logarithmic) interpolation.
class TabulatedFunction : public RealFunction {
public:
  TabulatedFunction(std::string parameter, std::vector<double> x, std::vector<double> y);
  std::vector<std::string> parameters() const override { return {parameter_}; }
  double evaluate(std::span<const double> values) const override;

  Extension left = Extension::Excluded;
  Extension right = Extension::Excluded;
  bool logX = false;
  bool logY = false;
  const std::vector<double>& abscissas() const { return x_; }
  const std::vector<double>& ordinates() const { return y_; }

private:
  double interpolate(std::size_t i, double x) const; // on [x_i, x_{i+1}]
  std::string parameter_;
  std::vector<double> x_;
  std::vector<double> y_;
};

// FORMULE: an expression compiled once.
class FormulaFunction : public RealFunction {
public:
  FormulaFunction(const std::string& text, std::vector<std::string> parameters,
                  std::vector<std::pair<std::string, double>> constants, const SourceLocation& origin);
  std::vector<std::string> parameters() const override { return formula_.parameters(); }
  double evaluate(std::span<const double> values) const override { return formula_(values); }

private:
  RealFormula formula_;
};

// DEFI_LIST_REEL: a list of reals (type listr8).
class RealList : public ConceptData {
public:
  explicit RealList(std::vector<double> list) : values(std::move(list)) {}
  std::vector<double> values;
};

} // namespace stella
