// Arithmetic and unary operators with Python's rules (int/float/complex promotion, floor division
// and modulo toward -infinity, sequence repetition and concatenation); comparisons are in
// ComparisonOperators.cpp, indexing and iteration in ContainerAccess.cpp.
#include "Runtime.hpp"
#include "SequenceObject.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stella {

void langError(std::string_view key, msg::Args args) {
  Diagnostic d = msg::make(key, args);
  STELLA_ASSERT(d.notes.size() <= 1, "a language error has one note at most");
  throw LangError{std::move(d.id), std::move(d.message), d.notes.empty() ? std::string() : d.notes.front()};
}

namespace {

using K = Value::Kind;

bool isIntLike(const Value& v) {
  return v.isInt() || v.isBool();
}
bool isComplex(const Value& v) {
  return v.kind() == K::Complex;
}
std::complex<double> toComplex(const Value& v) {
  return isComplex(v) ? v.asComplex() : std::complex<double>(v.asReal(), 0.0);
}

[[noreturn]] void unsupported(const char* op, const Value& a, const Value& b) {
  langError("LANG_TYPE.10", {{"op", op}, {"type_name", a.typeName()}, {"type_name_2", b.typeName()}});
}

[[noreturn]] void overflow() {
  langError("LANG_VALUE.2", {});
}

[[noreturn]] void divisionByZero(const char* what) {
  langError("LANG_ZERO", {{"what", std::string(what)}});
}

// Python raises OverflowError when a power of finite numbers is too large for a float (where
// `*` and `+` give inf): `2.0 ** 1e6`.
[[noreturn]] void powerOverflow(const Value& a, const Value& b) {
  langError("LANG_OVERFLOW", {{"repr", a.repr()}, {"repr_2", b.repr()}});
}

std::int64_t intPower(std::int64_t base, std::int64_t exponent) {
  std::int64_t result = 1;
  while (exponent > 0) {
    if ((exponent & 1) != 0 && __builtin_mul_overflow(result, base, &result)) {
      overflow();
    }
    exponent >>= 1;
    if (exponent > 0 && __builtin_mul_overflow(base, base, &base)) {
      overflow();
    }
  }
  return result;
}

double realPower(double a, double b) {
  if (a == 0.0 && b < 0.0) {
    divisionByZero("0.0 cannot be raised to a negative power: division");
  }
  if (a < 0.0 && b != std::floor(b)) {
    langError("LANG_VALUE.3", {});
  }
  double result = std::pow(a, b);
  if (std::isinf(result) && std::isfinite(a) && std::isfinite(b)) {
    powerOverflow(Value(a), Value(b));
  }
  return result;
}

Value repeat(const Value& seq, std::int64_t times, const RuntimeLimits& limits) {
  if (times < 0) {
    times = 0;
  }
  if (seq.isString()) {
    const std::string& s = seq.asString();
    if (!s.empty() && times > limits.maxStringLength / static_cast<std::int64_t>(s.size())) {
      langError("LANG_SIZE.2", {{"max_string_length", std::to_string(limits.maxStringLength)}});
    }
    chargeBulk(times, static_cast<std::int64_t>(s.size()));
    std::string out;
    out.reserve(s.size() * static_cast<std::size_t>(times));
    for (std::int64_t i = 0; i < times; ++i) {
      out += s;
    }
    return Value(std::move(out));
  }
  const ValueList& items = seq.items();
  if (!items.empty() && times > limits.maxSequenceLength / static_cast<std::int64_t>(items.size())) {
    langError("LANG_SIZE.3", {{"max_sequence_length", std::to_string(limits.maxSequenceLength)}});
  }
  chargeBulk(static_cast<std::int64_t>(items.size()) * times, sizeof(Value));
  ValueList out;
  out.reserve(items.size() * static_cast<std::size_t>(times));
  for (std::int64_t i = 0; i < times; ++i) {
    out.insert(out.end(), items.begin(), items.end());
  }
  return seq.isTuple() ? Value::tuple(std::move(out)) : Value::list(std::move(out));
}

Value concatenate(const Value& a, const Value& b, const RuntimeLimits& limits) {
  if (a.isString()) {
    if (static_cast<std::int64_t>(a.asString().size() + b.asString().size()) > limits.maxStringLength) {
      langError("LANG_SIZE.4", {});
    }
    chargeBulk(1, static_cast<std::int64_t>(a.asString().size() + b.asString().size()));
    return Value(a.asString() + b.asString());
  }
  const ValueList& more = b.items();
  if (static_cast<std::int64_t>(a.items().size() + more.size()) > limits.maxSequenceLength) {
    langError("LANG_SIZE.5", {});
  }
  chargeBulk(static_cast<std::int64_t>(a.items().size() + more.size()), sizeof(Value));
  ValueList out = a.items();
  out.insert(out.end(), more.begin(), more.end());
  return a.isTuple() ? Value::tuple(std::move(out)) : Value::list(std::move(out));
}

Value intArithmetic(BinaryOp op, std::int64_t x, std::int64_t y) {
  std::int64_t r = 0;
  switch (op) {
  case BinaryOp::Add:
    if (__builtin_add_overflow(x, y, &r)) {
      overflow();
    }
    return Value(r);
  case BinaryOp::Sub:
    if (__builtin_sub_overflow(x, y, &r)) {
      overflow();
    }
    return Value(r);
  case BinaryOp::Mul:
    if (__builtin_mul_overflow(x, y, &r)) {
      overflow();
    }
    return Value(r);
  case BinaryOp::Div:
    if (y == 0) {
      divisionByZero("division");
    }
    return Value(static_cast<double>(x) / static_cast<double>(y));
  case BinaryOp::FloorDiv: {
    if (y == 0) {
      divisionByZero("integer division");
    }
    if (x == std::numeric_limits<std::int64_t>::min() && y == -1) {
      overflow();
    }
    std::int64_t q = x / y;
    if ((x % y != 0) && ((x < 0) != (y < 0))) {
      --q;
    }
    return Value(q);
  }
  case BinaryOp::Mod: {
    if (y == 0) {
      divisionByZero("integer modulo");
    }
    if (y == -1) {
      return Value(std::int64_t{0});
    }
    std::int64_t m = x % y;
    if (m != 0 && ((m < 0) != (y < 0))) {
      m += y;
    }
    return Value(m);
  }
  case BinaryOp::Pow:
    if (y < 0) {
      return Value(realPower(static_cast<double>(x), static_cast<double>(y)));
    }
    return Value(intPower(x, y));
  case BinaryOp::BitAnd:
    return Value(x & y);
  case BinaryOp::BitOr:
    return Value(x | y);
  case BinaryOp::BitXor:
    return Value(x ^ y);
  case BinaryOp::LShift:
    if (y < 0) {
      langError("LANG_VALUE.4", {});
    }
    if (y >= 63 || (x != 0 && (x > (std::numeric_limits<std::int64_t>::max() >> y) ||
                               x < (std::numeric_limits<std::int64_t>::min() >> y)))) {
      if (x != 0) {
        overflow();
      }
      return Value(std::int64_t{0});
    }
    return Value(static_cast<std::int64_t>(static_cast<std::uint64_t>(x) << y));
  case BinaryOp::RShift:
    if (y < 0) {
      langError("LANG_VALUE.4", {});
    }
    return Value(y >= 63 ? (x < 0 ? std::int64_t{-1} : std::int64_t{0}) : (x >> y));
  }
  return Value();
}

Value realArithmetic(BinaryOp op, double x, double y, const Value& a, const Value& b) {
  switch (op) {
  case BinaryOp::Add:
    return Value(x + y);
  case BinaryOp::Sub:
    return Value(x - y);
  case BinaryOp::Mul:
    return Value(x * y);
  case BinaryOp::Div:
    if (y == 0.0) {
      divisionByZero("float division");
    }
    return Value(x / y);
  case BinaryOp::FloorDiv:
    if (y == 0.0) {
      divisionByZero("float floor division");
    }
    return Value(std::floor(x / y));
  case BinaryOp::Mod: {
    if (y == 0.0) {
      divisionByZero("float modulo");
    }
    double m = std::fmod(x, y);
    if (m != 0.0 && ((m < 0.0) != (y < 0.0))) {
      m += y;
    }
    return Value(m);
  }
  case BinaryOp::Pow:
    return Value(realPower(x, y));
  default:
    unsupported(binaryOpText(op), a, b);
  }
}

Value complexArithmetic(BinaryOp op, std::complex<double> x, std::complex<double> y, const Value& a,
                        const Value& b) {
  switch (op) {
  case BinaryOp::Add:
    return Value(x + y);
  case BinaryOp::Sub:
    return Value(x - y);
  case BinaryOp::Mul:
    return Value(x * y);
  case BinaryOp::Div:
    if (y == std::complex<double>(0.0, 0.0)) {
      divisionByZero("complex division");
    }
    return Value(x / y);
  case BinaryOp::Pow: {
    std::complex<double> result = std::pow(x, y);
    bool finiteOperands = std::isfinite(x.real()) && std::isfinite(x.imag()) && std::isfinite(y.real()) &&
                          std::isfinite(y.imag());
    if (finiteOperands && (std::isinf(result.real()) || std::isinf(result.imag()))) {
      powerOverflow(a, b);
    }
    return Value(result);
  }
  default:
    unsupported(binaryOpText(op), a, b);
  }
}

} // namespace

Value binaryOperation(BinaryOp op, const Value& a, const Value& b, const RuntimeLimits& limits) {
  if (isIntLike(a) && isIntLike(b)) {
    return intArithmetic(op, a.asInt(), b.asInt());
  }
  if (a.isNumber() && b.isNumber()) {
    return realArithmetic(op, a.asReal(), b.asReal(), a, b);
  }
  if ((isComplex(a) || a.isNumber()) && (isComplex(b) || b.isNumber())) {
    return complexArithmetic(op, toComplex(a), toComplex(b), a, b);
  }
  switch (op) {
  case BinaryOp::Add:
    if ((a.isString() && b.isString()) || (a.isList() && b.isList()) || (a.isTuple() && b.isTuple())) {
      return concatenate(a, b, limits);
    }
    if (a.isString() || b.isString()) {
      langError("LANG_TYPE.11", {{"type_name", a.typeName()}, {"type_name_2", b.typeName()}});
    }
    break;
  case BinaryOp::Mul:
    if ((a.isString() || a.isSequence()) && isIntLike(b)) {
      return repeat(a, b.asInt(), limits);
    }
    if (isIntLike(a) && (b.isString() || b.isSequence())) {
      return repeat(b, a.asInt(), limits);
    }
    break;
  case BinaryOp::Mod:
    if (a.isString()) {
      return Value(percentFormat(a.asString(), b));
    }
    break;
  default:
    break;
  }
  unsupported(binaryOpText(op), a, b);
}

Value unaryOperation(UnaryOp op, const Value& a) {
  switch (op) {
  case UnaryOp::Neg:
    if (isIntLike(a)) {
      if (a.asInt() == std::numeric_limits<std::int64_t>::min()) {
        overflow();
      }
      return Value(-a.asInt());
    }
    if (a.isReal()) {
      return Value(-a.asReal());
    }
    if (isComplex(a)) {
      return Value(-a.asComplex());
    }
    break;
  case UnaryOp::Plus:
    if (isIntLike(a)) {
      return Value(a.asInt());
    }
    if (a.isReal() || isComplex(a)) {
      return a;
    }
    break;
  case UnaryOp::Invert:
    if (isIntLike(a)) {
      return Value(~a.asInt());
    }
    break;
  }
  langError("LANG_TYPE.12", {{"unary_op_text", unaryOpText(op)}, {"type_name", a.typeName()}});
}

} // namespace stella
