#include "RealFunction.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella {

TabulatedFunction::TabulatedFunction(std::string parameter, std::vector<double> x, std::vector<double> y)
    : parameter_(std::move(parameter)), x_(std::move(x)), y_(std::move(y)) {
  STELLA_ASSERT(x_.size() == y_.size() && !x_.empty(), "abscissas and ordinates must match");
}

double TabulatedFunction::interpolate(std::size_t i, double x) const {
  double x0 = x_[i];
  double x1 = x_[i + 1];
  double y0 = y_[i];
  double y1 = y_[i + 1];
  double t = logX ? (std::log(x) - std::log(x0)) / (std::log(x1) - std::log(x0)) : (x - x0) / (x1 - x0);
  return logY ? std::exp(std::log(y0) + t * (std::log(y1) - std::log(y0))) : y0 + t * (y1 - y0);
}

double TabulatedFunction::evaluate(std::span<const double> values) const {
  STELLA_ASSERT(values.size() == 1, "a tabulated function has one parameter");
  double x = values[0];
  const std::size_t n = x_.size();
  if (n == 1) {
    return y_[0];
  }
  auto outside = [&](Extension e, bool leftSide) {
    std::size_t segment = leftSide ? 0 : n - 2;
    if (e == Extension::Constant) {
      return leftSide ? y_.front() : y_.back();
    }
    if (e == Extension::Linear) {
      return interpolate(segment, x);
    }
    throw UserError(msg::make("FUNCTION_1", {{"empty", name.empty() ? "(unnamed)" : name},
                                             {"parameter", parameter_},
                                             {"x", x},
                                             {"left_side", leftSide ? "left of" : "right of"},
                                             {"x_2", x_.front()},
                                             {"x_3", x_.back()},
                                             {"left_side_2", leftSide ? "PROL_GAUCHE" : "PROL_DROITE"}}));
  };
  if (x < x_.front()) {
    return outside(left, true);
  }
  if (x > x_.back()) {
    return outside(right, false);
  }
  auto it = std::upper_bound(x_.begin(), x_.end(), x);
  std::size_t i = it == x_.end() ? n - 2 : static_cast<std::size_t>(it - x_.begin()) - 1;
  i = std::min(i, n - 2);
  return interpolate(i, x);
}

FormulaFunction::FormulaFunction(const std::string& text, std::vector<std::string> parameters,
                                 std::vector<std::pair<std::string, double>> constants,
                                 const SourceLocation& origin)
    : formula_(text, std::move(parameters), std::move(constants), origin) {}

} // namespace stella
