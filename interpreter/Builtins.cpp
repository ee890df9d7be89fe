// Python's built-in functions available in command files (print, abs, round, the conversions,
// isinstance, type, _F...) and the dispatch of every built-in; the sequence ones are in
// BuiltinSequences.cpp, the math module in MathModule.cpp.
#include "BuiltinArguments.hpp"
#include "Exceptions.hpp"
#include "SequenceObject.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace stella {

namespace {

using Id = Builtin::Id;
using namespace builtins;

Value builtinValue(Id id, const char* name) {
  return Value(std::shared_ptr<Callable>(std::make_shared<Builtin>(id, name)));
}

Value absolute(const Value& v) {
  if (v.isInt() || v.isBool()) {
    if (v.asInt() == std::numeric_limits<std::int64_t>::min()) {
      langError("LANG_VALUE.27", {});
    }
    return Value(v.asInt() < 0 ? -v.asInt() : v.asInt());
  }
  if (v.isReal()) {
    return Value(std::fabs(v.asReal()));
  }
  if (v.kind() == Value::Kind::Complex) {
    return Value(std::abs(v.asComplex()));
  }
  langError("LANG_TYPE.23", {{"type_name", v.typeName()}});
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
      langError("LANG_VALUE.28", {{"repr", x.repr()}});
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
          langError("LANG_VALUE.29", {});
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
    langError("LANG_TYPE.24", {});
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
    langError("LANG_TYPE.25", {{"name", b->name()}});
  }
}

Value makeFactor(Evaluator& ev, const CallArguments& a, const Pos& at) {
  if (!a.positional.empty()) {
    langError("LANG_ARGS.10", {});
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
    ev.sink()->report(msg::make("PRINT", {{"text", text}}, ev.location(at)));
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
  langError("LANG_CALL", {{"name", name}});
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

} // namespace stella
