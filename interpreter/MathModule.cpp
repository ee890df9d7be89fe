// The math module available in command files (import math / from math import ...): functions
// with Python's domain and range errors, and the constants pi, e and inf.
#include "BuiltinArguments.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace stella {

namespace {

using builtins::arity;

[[noreturn]] void domainError(const char* fn, double x) {
  langError("LANG_VALUE.23", {{"fn", fn}, {"repr", Value(x).repr()}});
}

double realArgument(const CallArguments& a, std::size_t i) {
  return toReal(a.positional[i], "the argument");
}

Value unaryMath(const char* name, double (*fn)(double), bool (*valid)(double)) {
  std::string n = name;
  return makeNativeFunction(n, [n, fn, valid](const CallArguments& a) -> Value {
    arity(a, n, 1, 1);
    double x = realArgument(a, 0);
    if (valid != nullptr && !valid(x)) {
      domainError(n.c_str(), x);
    }
    double r = fn(x);
    if (std::isinf(r) && std::isfinite(x)) {
      langError("LANG_VALUE.24", {{"n", n}, {"repr", Value(x).repr()}});
    }
    return Value(r);
  });
}

Value binaryMath(const char* name, double (*fn)(double, double)) {
  std::string n = name;
  return makeNativeFunction(n, [n, fn](const CallArguments& a) -> Value {
    arity(a, n, 2, 2);
    double x = realArgument(a, 0);
    double y = realArgument(a, 1);
    if (n == "pow" && ((x < 0.0 && y != std::floor(y)) || (x == 0.0 && y < 0.0))) {
      langError("LANG_VALUE.25", {{"repr", Value(x).repr()}, {"repr_2", Value(y).repr()}});
    }
    if (n == "fmod" && y == 0.0) {
      langError("LANG_VALUE.26", {});
    }
    double r = fn(x, y);
    if (std::isinf(r) && std::isfinite(x) && std::isfinite(y)) {
      langError("LANG_OVERFLOW.2", {{"n", n}, {"repr", Value(x).repr()}, {"repr_2", Value(y).repr()}});
    }
    return Value(r);
  });
}

Value roundingMath(const char* name, double (*fn)(double)) {
  std::string n = name;
  return makeNativeFunction(n, [n, fn](const CallArguments& a) -> Value {
    arity(a, n, 1, 1);
    if (a.positional[0].isInt() || a.positional[0].isBool()) {
      return Value(a.positional[0].asInt());
    }
    double r = fn(realArgument(a, 0));
    if (!std::isfinite(r) || std::fabs(r) > 9.2e18) {
      langError("LANG_VALUE.20", {{"repr", Value(r).repr()}});
    }
    return Value(static_cast<std::int64_t>(r));
  });
}

} // namespace

const std::unordered_map<std::string, Value>& mathNames() {
  static const std::unordered_map<std::string, Value> names = [] {
    std::unordered_map<std::string, Value> n;
    auto nonNegative = [](double x) { return x >= 0.0; };
    auto positive = [](double x) { return x > 0.0; };
    auto unit = [](double x) { return x >= -1.0 && x <= 1.0; };
    auto finite = [](double x) { return std::isfinite(x); };
    n.emplace("sqrt", unaryMath(
                          "sqrt", [](double x) { return std::sqrt(x); }, nonNegative));
    n.emplace("exp", unaryMath(
                         "exp", [](double x) { return std::exp(x); }, nullptr));
    n.emplace("log10", unaryMath(
                           "log10", [](double x) { return std::log10(x); }, positive));
    n.emplace("sin", unaryMath(
                         "sin", [](double x) { return std::sin(x); }, finite));
    n.emplace("cos", unaryMath(
                         "cos", [](double x) { return std::cos(x); }, finite));
    n.emplace("tan", unaryMath(
                         "tan", [](double x) { return std::tan(x); }, finite));
    n.emplace("asin", unaryMath(
                          "asin", [](double x) { return std::asin(x); }, unit));
    n.emplace("acos", unaryMath(
                          "acos", [](double x) { return std::acos(x); }, unit));
    n.emplace("atan", unaryMath(
                          "atan", [](double x) { return std::atan(x); }, nullptr));
    n.emplace("sinh", unaryMath(
                          "sinh", [](double x) { return std::sinh(x); }, nullptr));
    n.emplace("cosh", unaryMath(
                          "cosh", [](double x) { return std::cosh(x); }, nullptr));
    n.emplace("tanh", unaryMath(
                          "tanh", [](double x) { return std::tanh(x); }, nullptr));
    n.emplace("fabs", unaryMath(
                          "fabs", [](double x) { return std::fabs(x); }, nullptr));
    n.emplace("degrees", unaryMath(
                             "degrees", [](double x) { return x * 180.0 / std::numbers::pi; }, nullptr));
    n.emplace("radians", unaryMath(
                             "radians", [](double x) { return x * std::numbers::pi / 180.0; }, nullptr));
    n.emplace("atan2", binaryMath("atan2", [](double y, double x) { return std::atan2(y, x); }));
    n.emplace("pow", binaryMath("pow", [](double x, double y) { return std::pow(x, y); }));
    n.emplace("hypot", binaryMath("hypot", [](double x, double y) { return std::hypot(x, y); }));
    n.emplace("fmod", binaryMath("fmod", [](double x, double y) { return std::fmod(x, y); }));
    n.emplace("floor", roundingMath("floor", [](double x) { return std::floor(x); }));
    n.emplace("ceil", roundingMath("ceil", [](double x) { return std::ceil(x); }));
    n.emplace("trunc", roundingMath("trunc", [](double x) { return std::trunc(x); }));
    n.emplace("log", makeNativeFunction("log", [](const CallArguments& a) -> Value {
                arity(a, "log", 1, 2);
                double x = realArgument(a, 0);
                if (x <= 0.0) {
                  domainError("log", x);
                }
                if (a.positional.size() == 1) {
                  return Value(std::log(x));
                }
                double base = realArgument(a, 1);
                if (base <= 0.0 || base == 1.0) {
                  domainError("log base", base);
                }
                return Value(std::log(x) / std::log(base));
              }));
    n.emplace("isnan", makeNativeFunction("isnan", [](const CallArguments& a) -> Value {
                arity(a, "isnan", 1, 1);
                return Value(std::isnan(realArgument(a, 0)));
              }));
    n.emplace("isinf", makeNativeFunction("isinf", [](const CallArguments& a) -> Value {
                arity(a, "isinf", 1, 1);
                return Value(std::isinf(realArgument(a, 0)));
              }));
    n.emplace("pi", Value(std::numbers::pi));
    n.emplace("e", Value(std::numbers::e));
    n.emplace("inf", Value(std::numeric_limits<double>::infinity()));
    return n;
  }();
  return names;
}

} // namespace stella
