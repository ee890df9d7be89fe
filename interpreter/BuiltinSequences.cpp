// Built-in functions over sequences and iterables: range, len, min, max, sum, zip, enumerate,
// sorted, map and filter.
#include "BuiltinArguments.hpp"
#include "Exceptions.hpp"
#include "SequenceObject.hpp"

#include <algorithm>
#include <limits>

namespace stella::builtins {

namespace {

std::int64_t utf8Length(const std::string& s) {
  std::int64_t n = 0;
  for (char c : s) {
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
      ++n;
    }
  }
  return n;
}

} // namespace

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
    langError("LANG_VALUE.33", {});
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
  langError("LANG_TYPE.30", {{"type_name", v.typeName()}});
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
    langError("LANG_VALUE.34", {{"name", std::string(name)}});
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

} // namespace stella::builtins
