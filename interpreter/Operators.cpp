// Arithmetic, comparison, membership and indexing with Python's rules (int/float promotion,
// floor division and modulo toward -infinity, sequence repetition and concatenation).
#include "Runtime.hpp"
#include "SequenceObject.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stella {

void langError(std::string id, std::string message, std::string note) {
  throw LangError{std::move(id), std::move(message), std::move(note)};
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
  langError("LANG_TYPE", std::string("unsupported operand types for ") + op + ": '" + a.typeName() +
                             "' and '" + b.typeName() + "'");
}

[[noreturn]] void overflow() {
  langError("LANG_VALUE", "integer result too large",
            "stella's integers have 64 bits; use a real number (e.g. 2.**70)");
}

[[noreturn]] void divisionByZero(const char* what) {
  langError("LANG_ZERO", std::string(what) + " by zero");
}

// Python raises OverflowError when a power of finite numbers is too large for a float (where
// `*` and `+` give inf): `2.0 ** 1e6`.
[[noreturn]] void powerOverflow(const Value& a, const Value& b) {
  langError("LANG_OVERFLOW",
            "numerical result out of range: " + a.repr() + " ** " + b.repr() +
                " is larger than the largest float (about 1.8e308)",
            "Python raises OverflowError here; check the exponent");
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
    langError("LANG_VALUE", "a negative number cannot be raised to a fractional power");
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
      langError("LANG_SIZE",
                "string too long (more than " + std::to_string(limits.maxStringLength) + " characters)");
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
    langError("LANG_SIZE",
              "sequence too long (more than " + std::to_string(limits.maxSequenceLength) + " items)");
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
      langError("LANG_SIZE", "string too long");
    }
    chargeBulk(1, static_cast<std::int64_t>(a.asString().size() + b.asString().size()));
    return Value(a.asString() + b.asString());
  }
  const ValueList& more = b.items();
  if (static_cast<std::int64_t>(a.items().size() + more.size()) > limits.maxSequenceLength) {
    langError("LANG_SIZE", "sequence too long");
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
      langError("LANG_VALUE", "negative shift count");
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
      langError("LANG_VALUE", "negative shift count");
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
      langError("LANG_TYPE", "cannot add '" + a.typeName() + "' and '" + b.typeName() + "'",
                "convert the number with str(...) or use formatting: 'x=%g' % x");
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
  langError("LANG_TYPE",
            std::string("bad operand type for unary ") + unaryOpText(op) + ": '" + a.typeName() + "'");
}

namespace {

int compareSequences(const ValueList& a, const ValueList& b, int depth);

// -1, 0, 1 like Python's ordering; LangError when the types are not ordered or nested too deep.
int order(const Value& a, const Value& b, int depth = 0) {
  if (a.isNumber() && b.isNumber()) {
    if (isIntLike(a) && isIntLike(b)) {
      return a.asInt() < b.asInt() ? -1 : (a.asInt() > b.asInt() ? 1 : 0);
    }
    double x = a.asReal();
    double y = b.asReal();
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  if (a.isString() && b.isString()) {
    int c = a.asString().compare(b.asString());
    return c < 0 ? -1 : (c > 0 ? 1 : 0);
  }
  if ((a.isTuple() && b.isTuple()) || (a.isList() && b.isList())) {
    if (depth >= maxValueNesting) {
      langError("LANG_DEPTH", "values nested too deeply to order (more than " +
                                  std::to_string(maxValueNesting) + " levels)");
    }
    return compareSequences(a.items(), b.items(), depth);
  }
  langError("LANG_TYPE",
            "cannot order '" + a.typeName() + "' and '" + b.typeName() + "' (with <, >, <=, >=)");
}

int compareSequences(const ValueList& a, const ValueList& b, int depth) {
  std::size_t n = std::min(a.size(), b.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!a[i].equals(b[i])) {
      return order(a[i], b[i], depth + 1);
    }
  }
  return a.size() < b.size() ? -1 : (a.size() > b.size() ? 1 : 0);
}

bool identical(const Value& a, const Value& b) {
  if (a.kind() != b.kind()) {
    return false;
  }
  switch (a.kind()) {
  case K::None:
    return true;
  case K::Bool:
    return a.asBool() == b.asBool();
  case K::Int:
  case K::Real:
  case K::String:
    return a.equals(b);
  case K::Tuple:
    return &a.items() == &b.items();
  default:
    return a.equals(b) && (a.kind() == K::Concept || a.kind() == K::Callable || a.kind() == K::Native ||
                           a.kind() == K::Factor || (a.isList() && a.asList() == b.asList()) ||
                           (a.isDict() && a.asDict() == b.asDict()));
  }
}

} // namespace

bool lessThan(const Value& a, const Value& b) {
  return order(a, b) < 0;
}

bool contains(const Value& container, const Value& item) {
  if (container.isString()) {
    if (!item.isString()) {
      langError("LANG_TYPE", "'in <string>' requires a string on the left, not '" + item.typeName() + "'");
    }
    return container.asString().find(item.asString()) != std::string::npos;
  }
  if (container.isSequence()) {
    for (const Value& v : container.items()) {
      if (v.equals(item)) {
        return true;
      }
    }
    return false;
  }
  if (container.isDict()) {
    return dictFind(*container.asDict(), item) != nullptr;
  }
  if (const RangeObject* r = asRange(container)) {
    if (!isIntLike(item) && !item.isReal()) {
      return false;
    }
    double x = item.asReal();
    if (x != std::floor(x)) {
      return false;
    }
    auto i = static_cast<std::int64_t>(x);
    if (r->step > 0 ? (i < r->start || i >= r->stop) : (i > r->start || i <= r->stop)) {
      return false;
    }
    return (i - r->start) % r->step == 0;
  }
  langError("LANG_TYPE", "argument of type '" + container.typeName() + "' is not a container (for 'in')");
}

bool compareOperation(CompareOp op, const Value& a, const Value& b) {
  switch (op) {
  case CompareOp::Eq:
    return a.equals(b);
  case CompareOp::Ne:
    return !a.equals(b);
  case CompareOp::Lt:
    return order(a, b) < 0;
  case CompareOp::Gt:
    return order(a, b) > 0;
  case CompareOp::Le:
    return order(a, b) <= 0;
  case CompareOp::Ge:
    return order(a, b) >= 0;
  case CompareOp::In:
    return contains(b, a);
  case CompareOp::NotIn:
    return !contains(b, a);
  case CompareOp::Is:
    return identical(a, b);
  case CompareOp::IsNot:
    return !identical(a, b);
  }
  return false;
}

std::int64_t RangeObject::size() const {
  // in unsigned arithmetic: stop - start may not fit in 64 signed bits
  std::uint64_t n = 0;
  if (step > 0 && stop > start) {
    n = (static_cast<std::uint64_t>(stop) - static_cast<std::uint64_t>(start) - 1) /
            static_cast<std::uint64_t>(step) +
        1;
  } else if (step < 0 && start > stop) {
    n = (static_cast<std::uint64_t>(start) - static_cast<std::uint64_t>(stop) - 1) /
            (static_cast<std::uint64_t>(-(step + 1)) + 1) +
        1;
  }
  return n > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())
             ? std::numeric_limits<std::int64_t>::max()
             : static_cast<std::int64_t>(n);
}

const RangeObject* asRange(const Value& v) {
  return v.isNative() ? dynamic_cast<const RangeObject*>(v.asNative().get()) : nullptr;
}

ValueList iterableItems(const Value& v, const RuntimeLimits& limits) {
  if (v.isSequence()) {
    chargeBulk(static_cast<std::int64_t>(v.items().size()), sizeof(Value));
    return v.items();
  }
  if (const RangeObject* r = asRange(v)) {
    if (r->size() > limits.maxSequenceLength) {
      langError("LANG_SIZE", "range too long to make a list (more than " +
                                 std::to_string(limits.maxSequenceLength) + " items)");
    }
  }
  ValueList out;
  forEachItem(v, [&](const Value& item) {
    out.push_back(item);
    if (out.size() == out.capacity()) {
      chargeAllocation(static_cast<std::int64_t>(out.capacity() * sizeof(Value)));
    }
    return true;
  });
  return out;
}

std::size_t normalizeIndex(std::int64_t index, std::size_t size, const char* what) {
  auto n = static_cast<std::int64_t>(size);
  std::int64_t i = index < 0 ? index + n : index;
  if (i < 0 || i >= n) {
    langError("LANG_INDEX",
              std::string(what) + " index " + std::to_string(index) + " out of range (size " +
                  std::to_string(size) + ")",
              size == 0 ? "the " + std::string(what) + " is empty"
                        : "valid indices are 0 to " + std::to_string(n - 1) + " (or -" + std::to_string(n) +
                              " to -1)");
  }
  return static_cast<std::size_t>(i);
}

std::int64_t toIndex(const Value& v, const char* what) {
  if (!isIntLike(v)) {
    langError("LANG_TYPE", std::string(what) + " must be an integer, not '" + v.typeName() + "'");
  }
  return v.asInt();
}

namespace {

// Python's slice.indices(): clamps bounds for a sequence of `size`.
struct SliceBounds {
  std::int64_t start, stop, step;
};

SliceBounds sliceBounds(const Value& slice, std::size_t size) {
  const ValueList& parts = slice.items(); // (lower, upper, step) as a tuple tagged by the evaluator
  auto n = static_cast<std::int64_t>(size);
  std::int64_t step = parts[2].isNone() ? 1 : toIndex(parts[2], "slice step");
  if (step == 0) {
    langError("LANG_VALUE", "slice step cannot be zero");
  }
  auto clamp = [&](const Value& v, std::int64_t dflt) {
    if (v.isNone()) {
      return dflt;
    }
    std::int64_t i = toIndex(v, "slice index");
    if (i < 0) {
      i += n;
      if (i < 0) {
        i = step < 0 ? -1 : 0;
      }
    } else if (i >= n) {
      i = step < 0 ? n - 1 : n;
    }
    return i;
  };
  std::int64_t start = clamp(parts[0], step < 0 ? n - 1 : 0);
  std::int64_t stop = clamp(parts[1], step < 0 ? -1 : n);
  return {start, stop, step};
}

} // namespace

// A slice value is a Native SliceObject made by the evaluator.
class SliceObject : public NativeObject {
public:
  explicit SliceObject(Value bounds) : parts(std::move(bounds)) {}
  std::string typeName() const override { return "slice"; }
  Value parts;
};

Value makeSlice(Value lower, Value upper, Value step) {
  return Value(std::shared_ptr<NativeObject>(
      std::make_shared<SliceObject>(Value::tuple({std::move(lower), std::move(upper), std::move(step)}))));
}

namespace {
const SliceObject* asSlice(const Value& v) {
  return v.isNative() ? dynamic_cast<const SliceObject*>(v.asNative().get()) : nullptr;
}

template <class Seq, class Get> Seq sliceOf(std::size_t size, const SliceObject& slice, Get get) {
  SliceBounds b = sliceBounds(slice.parts, size);
  Seq out;
  if (b.step > 0) {
    for (std::int64_t i = b.start; i < b.stop; i += b.step) {
      get(out, static_cast<std::size_t>(i));
    }
  } else {
    for (std::int64_t i = b.start; i > b.stop; i += b.step) {
      get(out, static_cast<std::size_t>(i));
    }
  }
  return out;
}
} // namespace

Value getItem(const Value& container, const Value& index) {
  if (const SliceObject* slice = asSlice(index)) {
    if (container.isString()) {
      const std::string& s = container.asString();
      return Value(
          sliceOf<std::string>(s.size(), *slice, [&](std::string& out, std::size_t i) { out += s[i]; }));
    }
    if (container.isSequence()) {
      const ValueList& items = container.items();
      ValueList out = sliceOf<ValueList>(items.size(), *slice,
                                         [&](ValueList& o, std::size_t i) { o.push_back(items[i]); });
      return container.isTuple() ? Value::tuple(std::move(out)) : Value::list(std::move(out));
    }
    langError("LANG_TYPE", "'" + container.typeName() + "' object cannot be sliced");
  }
  if (container.isSequence()) {
    const ValueList& items = container.items();
    return items[normalizeIndex(toIndex(index, "list index"), items.size(), container.typeName().c_str())];
  }
  if (container.isString()) {
    const std::string& s = container.asString();
    return Value(std::string(1, s[normalizeIndex(toIndex(index, "string index"), s.size(), "string")]));
  }
  if (container.isDict()) {
    checkHashable(index);
    const Value* v = dictFind(*container.asDict(), index);
    if (v == nullptr) {
      langError("LANG_KEY", "key " + index.repr() + " not found in the dict");
    }
    return *v;
  }
  if (const RangeObject* r = asRange(container)) {
    return Value(r->at(static_cast<std::int64_t>(
        normalizeIndex(toIndex(index, "range index"), static_cast<std::size_t>(r->size()), "range"))));
  }
  if (const auto* seq =
          container.isNative() ? dynamic_cast<const SequenceObject*>(container.asNative().get()) : nullptr) {
    const std::string what = container.typeName();
    return seq->item(static_cast<std::int64_t>(
        normalizeIndex(toIndex(index, "index"), static_cast<std::size_t>(seq->length()), what.c_str())));
  }
  langError("LANG_TYPE", "'" + container.typeName() + "' object is not subscriptable",
            container.isConcept()
                ? "a concept's contents are read with commands or its methods, e.g. TAB.EXTR_TABLE()"
                : "");
}

void setItem(const Value& container, const Value& index, const Value& value) {
  if (container.isList()) {
    if (asSlice(index) != nullptr) {
      langError("LANG_TYPE", "assignment to a slice is not supported", "assign the elements one by one");
    }
    auto& items = container.asList()->items;
    items[normalizeIndex(toIndex(index, "list index"), items.size(), "list")] = value;
    return;
  }
  if (container.isDict()) {
    dictSet(*container.asDict(), index, value);
    return;
  }
  langError("LANG_TYPE", "'" + container.typeName() + "' object does not support item assignment",
            container.isTuple() ? "tuples cannot be changed; use a list [...] instead" : "");
}

void deleteItem(const Value& container, const Value& index) {
  if (container.isList()) {
    auto& items = container.asList()->items;
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(
                                    normalizeIndex(toIndex(index, "list index"), items.size(), "list")));
    return;
  }
  if (container.isDict()) {
    auto& items = container.asDict()->items;
    for (auto it = items.begin(); it != items.end(); ++it) {
      if (it->first.equals(index)) {
        items.erase(it);
        return;
      }
    }
    langError("LANG_KEY", "key " + index.repr() + " not found in the dict");
  }
  langError("LANG_TYPE", "'" + container.typeName() + "' object does not support item deletion");
}

void checkHashable(const Value& key) {
  if (key.isList() || key.isDict()) {
    langError("LANG_TYPE", "a '" + key.typeName() + "' cannot be a dict key",
              "use a tuple instead of a list");
  }
}

const Value* dictFind(const DictObject& dict, const Value& key) {
  for (const auto& [k, v] : dict.items) {
    if (k.equals(key)) {
      return &v;
    }
  }
  return nullptr;
}

void dictSet(DictObject& dict, const Value& key, const Value& value) {
  checkHashable(key);
  for (auto& [k, v] : dict.items) {
    if (k.equals(key)) {
      v = value;
      return;
    }
  }
  dict.items.emplace_back(key, value);
}

} // namespace stella
