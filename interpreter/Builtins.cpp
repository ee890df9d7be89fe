// Python's built-in functions available in command files (range, len, min, max, sorted, _F,
// print...) and the math module.
#include "Evaluator.hpp"
#include "Exceptions.hpp"
#include "SequenceObject.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

namespace stella {

namespace {

using Id = Builtin::Id;

Value builtinValue(Id id, const char* name) {
  return Value(std::shared_ptr<Callable>(std::make_shared<Builtin>(id, name)));
}

void arity(const CallArguments& a, const std::string& name, std::size_t min, std::size_t max) {
  if (a.positional.size() < min || a.positional.size() > max) {
    std::string expected =
        min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max);
    if (max == min + 1000) {
      expected = "at least " + std::to_string(min);
    }
    langError("LANG_ARGS", name + "() takes " + expected + " positional arguments but " +
                               std::to_string(a.positional.size()) + " were given");
  }
}

void onlyKeywords(const CallArguments& a, const std::string& name,
                  std::initializer_list<const char*> allowed) {
  for (const auto& kw : a.keywords) {
    bool ok = false;
    for (const char* k : allowed) {
      ok = ok || kw.name == k;
    }
    if (!ok) {
      langError("LANG_ARGS", name + "() got an unexpected keyword argument '" + kw.name + "'");
    }
  }
}

const Value* keyword(const CallArguments& a, const char* name) {
  const KeywordArgument* kw = a.find(name);
  return kw != nullptr ? kw->value.get() : nullptr;
}

std::int64_t utf8Length(const std::string& s) {
  std::int64_t n = 0;
  for (char c : s) {
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
      ++n;
    }
  }
  return n;
}

Value makeRange(const CallArguments& a) {
  arity(a, "range", 1, 3);
  onlyKeywords(a, "range", {});
  std::int64_t start = 0;
  std::int64_t stop = 0;
  std::int64_t step = 1;
  if (a.positional.size() == 1) {
    stop = toIndex(a.positional[0], "range() argument");
  } else {
    start = toIndex(a.positional[0], "range() argument");
    stop = toIndex(a.positional[1], "range() argument");
    if (a.positional.size() == 3) {
      step = toIndex(a.positional[2], "range() step");
    }
  }
  if (step == 0) {
    langError("LANG_VALUE", "range() step must not be zero");
  }
  return Value(std::shared_ptr<NativeObject>(std::make_shared<RangeObject>(start, stop, step)));
}

Value length(const Value& v) {
  if (v.isString()) {
    return Value(utf8Length(v.asString()));
  }
  if (v.isSequence()) {
    return Value(static_cast<std::int64_t>(v.items().size()));
  }
  if (v.isDict()) {
    return Value(static_cast<std::int64_t>(v.asDict()->items.size()));
  }
  if (v.isFactor()) {
    return Value(static_cast<std::int64_t>(v.asFactor()->keywords.size()));
  }
  if (const RangeObject* r = asRange(v)) {
    return Value(r->size());
  }
  if (const auto* seq = v.isNative() ? dynamic_cast<const SequenceObject*>(v.asNative().get()) : nullptr) {
    return Value(seq->length());
  }
  langError("LANG_TYPE", "object of type '" + v.typeName() + "' has no len()");
}

Value absolute(const Value& v) {
  if (v.isInt() || v.isBool()) {
    if (v.asInt() == std::numeric_limits<std::int64_t>::min()) {
      langError("LANG_VALUE", "integer result too large");
    }
    return Value(v.asInt() < 0 ? -v.asInt() : v.asInt());
  }
  if (v.isReal()) {
    return Value(std::fabs(v.asReal()));
  }
  if (v.kind() == Value::Kind::Complex) {
    return Value(std::abs(v.asComplex()));
  }
  langError("LANG_TYPE", "bad operand type for abs(): '" + v.typeName() + "'");
}

Value extreme(Evaluator& ev, const CallArguments& a, const Pos& at, bool wantMax) {
  const char* name = wantMax ? "max" : "min";
  onlyKeywords(a, name, {"key", "default"});
  if (a.positional.empty()) {
    arity(a, name, 1, 1001);
  }
  ValueList items =
      a.positional.size() == 1 ? iterableItems(a.positional[0], ev.options().limits) : a.positional;
  if (items.empty()) {
    if (const Value* d = keyword(a, "default")) {
      return *d;
    }
    langError("LANG_VALUE", std::string(name) + "() of an empty sequence");
  }
  const Value* key = keyword(a, "key");
  auto keyOf = [&](const Value& v) {
    if (key == nullptr || key->isNone()) {
      return v;
    }
    CallArguments args;
    args.positional.push_back(v);
    return ev.call(*key, args, at);
  };
  Value best = items[0];
  Value bestKey = keyOf(best);
  for (std::size_t i = 1; i < items.size(); ++i) {
    Value k = keyOf(items[i]);
    if (wantMax ? lessThan(bestKey, k) : lessThan(k, bestKey)) {
      best = items[i];
      bestKey = k;
    }
  }
  return best;
}

Value sum(Evaluator& ev, const CallArguments& a) {
  arity(a, "sum", 1, 2);
  onlyKeywords(a, "sum", {"start"});
  Value total = a.positional.size() == 2 ? a.positional[1] : Value(std::int64_t{0});
  if (const Value* s = keyword(a, "start")) {
    total = *s;
  }
  for (const Value& item : iterableItems(a.positional[0], ev.options().limits)) {
    total = binaryOperation(BinaryOp::Add, total, item, ev.options().limits);
  }
  return total;
}

Value roundValue(const CallArguments& a) {
  arity(a, "round", 1, 2);
  const Value& x = a.positional[0];
  if (x.isInt() || x.isBool()) {
    return Value(x.asInt());
  }
  double d = toReal(x, "round() argument");
  if (a.positional.size() == 1 || a.positional[1].isNone()) {
    double r = std::nearbyint(d);
    if (!std::isfinite(r) || std::fabs(r) > 9.2e18) {
      langError("LANG_VALUE", "cannot round " + x.repr() + " to an integer");
    }
    return Value(static_cast<std::int64_t>(r));
  }
  std::int64_t n = toIndex(a.positional[1], "round() ndigits");
  if (n > 300 || n < -300) {
    return Value(d);
  }
  if (n < 0 || !std::isfinite(d)) {
    double scale = std::pow(10.0, static_cast<double>(-n));
    return Value(std::nearbyint(d / scale) * scale);
  }
  // correctly rounded on the exact binary value, like Python (round(2.675, 2) == 2.67)
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, "%.*f", static_cast<int>(n), d);
  return Value(std::strtod(buffer, nullptr));
}

Value zip(Evaluator& ev, const CallArguments& a) {
  onlyKeywords(a, "zip", {});
  std::vector<ValueList> lists;
  std::size_t n = a.positional.empty() ? 0 : static_cast<std::size_t>(-1);
  for (const auto& v : a.positional) {
    lists.push_back(iterableItems(v, ev.options().limits));
    n = std::min(n, lists.back().size());
  }
  ValueList out;
  for (std::size_t i = 0; i < n; ++i) {
    ValueList row;
    for (const auto& l : lists) {
      row.push_back(l[i]);
    }
    out.push_back(Value::tuple(std::move(row)));
  }
  return Value::list(std::move(out));
}

Value enumerate(Evaluator& ev, const CallArguments& a) {
  arity(a, "enumerate", 1, 2);
  onlyKeywords(a, "enumerate", {"start"});
  std::int64_t start = a.positional.size() == 2 ? toIndex(a.positional[1], "enumerate() start") : 0;
  if (const Value* s = keyword(a, "start")) {
    start = toIndex(*s, "enumerate() start");
  }
  ValueList out;
  for (Value& item : iterableItems(a.positional[0], ev.options().limits)) {
    out.push_back(Value::tuple({Value(start++), std::move(item)}));
  }
  return Value::list(std::move(out));
}

Value makeDict(Evaluator& ev, const CallArguments& a) {
  arity(a, "dict", 0, 1);
  auto dict = std::make_shared<DictObject>();
  if (a.positional.size() == 1) {
    const Value& src = a.positional[0];
    if (src.isDict()) {
      dict->items = src.asDict()->items;
    } else {
      for (const Value& pair : iterableItems(src, ev.options().limits)) {
        if (!pair.isSequence() || pair.items().size() != 2) {
          langError("LANG_VALUE", "dict() needs pairs (key, value)");
        }
        dictSet(*dict, pair.items()[0], pair.items()[1]);
      }
    }
  }
  for (const auto& kw : a.keywords) {
    dictSet(*dict, Value(kw.name), *kw.value);
  }
  return Value(dict);
}

bool isInstanceOf(const Value& v, const Value& type) {
  if (type.isTuple()) {
    for (const Value& t : type.items()) {
      if (isInstanceOf(v, t)) {
        return true;
      }
    }
    return false;
  }
  if (const auto* cls =
          type.isCallable() ? dynamic_cast<const ExceptionClass*>(type.asCallable().get()) : nullptr) {
    const auto* e = v.isNative() ? dynamic_cast<const ExceptionObject*>(v.asNative().get()) : nullptr;
    return e != nullptr && e->exceptionClass().isSubclassOf(*cls);
  }
  const Builtin* b = type.isCallable() ? dynamic_cast<const Builtin*>(type.asCallable().get()) : nullptr;
  if (b == nullptr) {
    langError("LANG_TYPE",
              "isinstance() needs a type (int, float, str, bool, list, tuple, dict) or a tuple of types");
  }
  switch (b->id) {
  case Id::Int:
    return v.isInt() || v.isBool();
  case Id::Float:
    return v.isReal();
  case Id::Str:
    return v.isString();
  case Id::Bool:
    return v.isBool();
  case Id::List:
    return v.isList();
  case Id::Tuple:
    return v.isTuple();
  case Id::Dict:
    return v.isDict();
  default:
    langError("LANG_TYPE", "isinstance() needs a type, not the function " + b->name() + "()");
  }
}

Value sorted(Evaluator& ev, const CallArguments& a, const Pos& at) {
  arity(a, "sorted", 1, 1);
  onlyKeywords(a, "sorted", {"key", "reverse"});
  ValueList items = iterableItems(a.positional[0], ev.options().limits);
  const Value* key = keyword(a, "key");
  bool reverse = keyword(a, "reverse") != nullptr && keyword(a, "reverse")->truthy();
  std::vector<std::pair<Value, Value>> keyed;
  keyed.reserve(items.size());
  for (Value& v : items) {
    Value k = v;
    if (key != nullptr && !key->isNone()) {
      CallArguments args;
      args.positional.push_back(v);
      k = ev.call(*key, args, at);
    }
    keyed.emplace_back(std::move(k), std::move(v));
  }
  std::stable_sort(keyed.begin(), keyed.end(), [&](const auto& x, const auto& y) {
    return reverse ? lessThan(y.first, x.first) : lessThan(x.first, y.first);
  });
  ValueList out;
  out.reserve(keyed.size());
  for (auto& [k, v] : keyed) {
    out.push_back(std::move(v));
  }
  return Value::list(std::move(out));
}

Value makeFactor(Evaluator& ev, const CallArguments& a, const Pos& at) {
  if (!a.positional.empty()) {
    langError("LANG_ARGS", "_F() takes keyword arguments only, e.g. _F(GROUP_MA='Top', DX=0.0)");
  }
  auto f = std::make_shared<FactorObject>();
  f->keywords = a.keywords;
  f->location = ev.location(at);
  return Value(f);
}

Value typeOf(const Value& v) {
  switch (v.kind()) {
  case Value::Kind::Int:
    return builtinNames().at("int");
  case Value::Kind::Real:
    return builtinNames().at("float");
  case Value::Kind::String:
    return builtinNames().at("str");
  case Value::Kind::Bool:
    return builtinNames().at("bool");
  case Value::Kind::List:
    return builtinNames().at("list");
  case Value::Kind::Tuple:
    return builtinNames().at("tuple");
  case Value::Kind::Dict:
    return builtinNames().at("dict");
  case Value::Kind::Native:
    if (const auto* e = dynamic_cast<const ExceptionObject*>(v.asNative().get())) {
      return exceptionNames().at(e->exceptionClass().name());
    }
    return Value(v.typeName());
  default:
    return Value(v.typeName());
  }
}

Value callEach(Evaluator& ev, const CallArguments& a, const Pos& at, bool filter) {
  const char* name = filter ? "filter" : "map";
  arity(a, name, 2, 2);
  ValueList out;
  for (Value& item : iterableItems(a.positional[1], ev.options().limits)) {
    if (filter && a.positional[0].isNone()) {
      if (item.truthy()) {
        out.push_back(std::move(item));
      }
      continue;
    }
    CallArguments args;
    args.positional.push_back(item);
    Value r = ev.call(a.positional[0], args, at);
    if (!filter) {
      out.push_back(std::move(r));
    } else if (r.truthy()) {
      out.push_back(std::move(item));
    }
  }
  return Value::list(std::move(out));
}

Value print(Evaluator& ev, const CallArguments& a, const Pos& at) {
  onlyKeywords(a, "print", {"sep", "end", "file", "flush"});
  std::string sep = " ";
  std::string end = "\n";
  if (const Value* s = keyword(a, "sep"); s != nullptr && !s->isNone()) {
    sep = s->str();
  }
  if (const Value* e = keyword(a, "end"); e != nullptr && !e->isNone()) {
    end = e->str();
  }
  std::string text;
  for (std::size_t i = 0; i < a.positional.size(); ++i) {
    if (i > 0) {
      text += sep;
    }
    text += a.positional[i].str();
  }
  if (end != "\n") {
    text += end;
  }
  if (ev.sink() != nullptr) {
    ev.sink()->report(Diagnostic::info("PRINT", text, ev.location(at)));
  }
  return Value();
}

Value callBuiltinUnlocated(Evaluator& ev, const Builtin& b, const CallArguments& a, const Pos& at) {
  const std::string& name = b.name();
  auto noKeywords = [&] { onlyKeywords(a, name, {}); };
  switch (b.id) {
  case Id::Print:
    return print(ev, a, at);
  case Id::Range:
    return makeRange(a);
  case Id::Len:
    arity(a, name, 1, 1);
    noKeywords();
    return length(a.positional[0]);
  case Id::Abs:
    arity(a, name, 1, 1);
    noKeywords();
    return absolute(a.positional[0]);
  case Id::Min:
    return extreme(ev, a, at, false);
  case Id::Max:
    return extreme(ev, a, at, true);
  case Id::Sum:
    return sum(ev, a);
  case Id::Float:
    arity(a, name, 0, 1);
    noKeywords();
    return a.positional.empty() ? Value(0.0) : toFloat(a.positional[0]);
  case Id::Int:
    arity(a, name, 0, 1);
    noKeywords();
    return a.positional.empty() ? Value(std::int64_t{0}) : toInt(a.positional[0]);
  case Id::Str:
    arity(a, name, 0, 1);
    noKeywords();
    return a.positional.empty() ? Value(std::string()) : Value(a.positional[0].str());
  case Id::Bool:
    arity(a, name, 0, 1);
    noKeywords();
    return Value(!a.positional.empty() && a.positional[0].truthy());
  case Id::Round:
    noKeywords();
    return roundValue(a);
  case Id::Zip:
    return zip(ev, a);
  case Id::Enumerate:
    return enumerate(ev, a);
  case Id::List:
    arity(a, name, 0, 1);
    noKeywords();
    return Value::list(a.positional.empty() ? ValueList{}
                                            : iterableItems(a.positional[0], ev.options().limits));
  case Id::Tuple:
    arity(a, name, 0, 1);
    noKeywords();
    return Value::tuple(a.positional.empty() ? ValueList{}
                                             : iterableItems(a.positional[0], ev.options().limits));
  case Id::Dict:
    return makeDict(ev, a);
  case Id::IsInstance:
    arity(a, name, 2, 2);
    return Value(isInstanceOf(a.positional[0], a.positional[1]));
  case Id::Sorted:
    return sorted(ev, a, at);
  case Id::Reversed: {
    arity(a, name, 1, 1);
    ValueList items = iterableItems(a.positional[0], ev.options().limits);
    std::reverse(items.begin(), items.end());
    return Value::list(std::move(items));
  }
  case Id::Any:
  case Id::All: {
    arity(a, name, 1, 1);
    bool any = b.id == Id::Any;
    bool result = !any;
    forEachItem(a.positional[0], [&](const Value& v) {
      if (v.truthy() == any) {
        result = any;
        return false;
      }
      return true;
    });
    return Value(result);
  }
  case Id::Repr:
    arity(a, name, 1, 1);
    return Value(a.positional[0].repr());
  case Id::Factor:
    return makeFactor(ev, a, at);
  case Id::Pow:
    arity(a, name, 2, 2);
    return binaryOperation(BinaryOp::Pow, a.positional[0], a.positional[1], ev.options().limits);
  case Id::DivMod:
    arity(a, name, 2, 2);
    return Value::tuple(
        {binaryOperation(BinaryOp::FloorDiv, a.positional[0], a.positional[1], ev.options().limits),
         binaryOperation(BinaryOp::Mod, a.positional[0], a.positional[1], ev.options().limits)});
  case Id::Type:
    arity(a, name, 1, 1);
    return typeOf(a.positional[0]);
  case Id::Map:
    return callEach(ev, a, at, false);
  case Id::Filter:
    return callEach(ev, a, at, true);
  }
  langError("LANG_CALL", name + "() is not available");
}

// --- math ---

[[noreturn]] void domainError(const char* fn, double x) {
  langError("LANG_VALUE",
            std::string("math domain error: ") + fn + "(" + Value(x).repr() + ") is not defined");
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
      langError("LANG_VALUE", "math range error: " + n + "(" + Value(x).repr() + ") is too large");
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
      langError("LANG_VALUE", "math domain error: pow(" + Value(x).repr() + ", " + Value(y).repr() + ")");
    }
    if (n == "fmod" && y == 0.0) {
      langError("LANG_VALUE", "math domain error: fmod(x, 0)");
    }
    double r = fn(x, y);
    if (std::isinf(r) && std::isfinite(x) && std::isfinite(y)) {
      langError("LANG_OVERFLOW",
                "math range error: " + n + "(" + Value(x).repr() + ", " + Value(y).repr() +
                    ") is larger than the largest float (about 1.8e308)",
                "Python raises OverflowError here");
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
      langError("LANG_VALUE", "cannot convert " + Value(r).repr() + " to an integer");
    }
    return Value(static_cast<std::int64_t>(r));
  });
}

} // namespace

Value callBuiltin(Evaluator& ev, const Builtin& b, const CallArguments& args, const Pos& at) {
  try {
    return callBuiltinUnlocated(ev, b, args, at);
  } catch (const LangError& e) {
    ev.raise(at, e);
  }
}

const std::unordered_map<std::string, Value>& builtinNames() {
  static const std::unordered_map<std::string, Value> names = [] {
    std::unordered_map<std::string, Value> n;
    const std::pair<Id, const char*> table[] = {
        {Id::Print, "print"},   {Id::Range, "range"},
        {Id::Len, "len"},       {Id::Abs, "abs"},
        {Id::Min, "min"},       {Id::Max, "max"},
        {Id::Sum, "sum"},       {Id::Float, "float"},
        {Id::Int, "int"},       {Id::Str, "str"},
        {Id::Bool, "bool"},     {Id::Round, "round"},
        {Id::Zip, "zip"},       {Id::Enumerate, "enumerate"},
        {Id::List, "list"},     {Id::Tuple, "tuple"},
        {Id::Dict, "dict"},     {Id::IsInstance, "isinstance"},
        {Id::Sorted, "sorted"}, {Id::Reversed, "reversed"},
        {Id::Any, "any"},       {Id::All, "all"},
        {Id::Repr, "repr"},     {Id::Factor, "_F"},
        {Id::Pow, "pow"},       {Id::DivMod, "divmod"},
        {Id::Type, "type"},     {Id::Map, "map"},
        {Id::Filter, "filter"},
    };
    for (const auto& [id, name] : table) {
      n.emplace(name, builtinValue(id, name));
    }
    for (const auto& [name, value] : exceptionNames()) {
      n.emplace(name, value);
    }
    return n;
  }();
  return names;
}

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
