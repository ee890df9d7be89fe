#pragma once
// The operations of the language on values, with Python's rules: arithmetic, comparison,
// indexing, string formatting, ranges. They throw LangError (id and message, no location); the
// evaluator adds the location of the expression being evaluated and throws UserError.

#include "Ast.hpp"
#include "SequenceObject.hpp"
#include "Value.hpp"
#include "WorkMeter.hpp"
#include "messages/Messages.hpp"

#include <cstdint>
#include <string>

namespace stella {

struct LangError {
  std::string id;
  std::string message;
  std::string note;
};

// Throws the LangError of catalogue entry `key` (messages/language.msg) formatted with `args`.
[[noreturn]] void langError(std::string_view key, msg::Args args = {});

// Sizes the language refuses to build (a list of more items, a longer string).
struct RuntimeLimits {
  std::int64_t maxSequenceLength = 10'000'000;
  std::int64_t maxStringLength = 100'000'000;
};

Value binaryOperation(BinaryOp op, const Value& a, const Value& b, const RuntimeLimits& limits);
Value unaryOperation(UnaryOp op, const Value& a);
bool compareOperation(CompareOp op, const Value& a, const Value& b);
// Python's `a < b` (numbers, strings, sequences); LangError for other types.
bool lessThan(const Value& a, const Value& b);
bool contains(const Value& container, const Value& item);

// `range(...)`: iterated lazily by for loops.
class RangeObject : public NativeObject {
public:
  RangeObject(std::int64_t first, std::int64_t end, std::int64_t increment)
      : start(first), stop(end), step(increment) {}
  std::string typeName() const override { return "range"; }
  std::int64_t size() const;
  // start + i * step, computed without signed overflow (the result is in range by construction)
  std::int64_t at(std::int64_t i) const {
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(start) +
                                     static_cast<std::uint64_t>(i) * static_cast<std::uint64_t>(step));
  }
  std::int64_t start;
  std::int64_t stop;
  std::int64_t step;
};

const RangeObject* asRange(const Value& v);

// Calls `f` on each item of an iterable (list, tuple, str, dict keys, range); LangError when the
// value is not iterable. `f` returns false to stop.
template <class F> void forEachItem(const Value& v, F&& f);

// Materialises an iterable as a list of values.
ValueList iterableItems(const Value& v, const RuntimeLimits& limits);

// `a[lower:upper:step]` as an index value (a native 'slice' object).
Value makeSlice(Value lower, Value upper, Value step);
Value getItem(const Value& container, const Value& index);
void setItem(const Value& container, const Value& index, const Value& value);
void deleteItem(const Value& container, const Value& index);
// Normalises a Python index (negative from the end); LangError when out of range.
std::size_t normalizeIndex(std::int64_t index, std::size_t size, const char* what);
// Dictionary helpers (keys compared with Python equality; lists and dicts are not keys).
void checkHashable(const Value& key);
const Value* dictFind(const DictObject& dict, const Value& key);
void dictSet(DictObject& dict, const Value& key, const Value& value);

// `'%d %s' % args`
std::string percentFormat(const std::string& format, const Value& args);
// format(value, spec) with Python's format mini-language.
std::string formatWithSpec(const Value& value, const std::string& spec);
// `'{} {x}'.format(...)`
std::string braceFormat(const std::string& format, const ValueList& positional,
                        const std::vector<KeywordArgument>& keywords);

// Python's int(x) / float(x) conversions of strings and numbers.
Value toInt(const Value& v);
Value toFloat(const Value& v);
double toReal(const Value& v, const char* what);
std::int64_t toIndex(const Value& v, const char* what);

template <class F> void forEachItem(const Value& v, F&& f) {
  switch (v.kind()) {
  case Value::Kind::Tuple: {
    auto keep = v; // the tuple's storage stays alive while iterating
    for (const Value& item : keep.items()) {
      chargeOperation();
      if (!f(item)) {
        return;
      }
    }
    return;
  }
  case Value::Kind::List: {
    auto list = v.asList();
    for (std::size_t i = 0; i < list->items.size(); ++i) {
      Value item = list->items[i];
      chargeOperation();
      if (!f(item)) {
        return;
      }
    }
    return;
  }
  case Value::Kind::String: {
    const std::string& s = v.asString();
    for (std::size_t i = 0; i < s.size();) {
      std::size_t len = 1;
      auto c = static_cast<unsigned char>(s[i]);
      if (c >= 0xF0) {
        len = 4;
      } else if (c >= 0xE0) {
        len = 3;
      } else if (c >= 0xC0) {
        len = 2;
      }
      len = std::min(len, s.size() - i);
      chargeOperation();
      if (!f(Value(s.substr(i, len)))) {
        return;
      }
      i += len;
    }
    return;
  }
  case Value::Kind::Dict: {
    auto dict = v.asDict();
    for (std::size_t i = 0; i < dict->items.size(); ++i) {
      Value key = dict->items[i].first;
      chargeOperation();
      if (!f(key)) {
        return;
      }
    }
    return;
  }
  default:
    if (const RangeObject* r = asRange(v)) {
      std::int64_t n = r->size();
      for (std::int64_t i = 0; i < n; ++i) {
        chargeOperation();
        if (!f(Value(r->at(i)))) {
          return;
        }
      }
      return;
    }
    if (const auto* seq = v.isNative() ? dynamic_cast<const SequenceObject*>(v.asNative().get()) : nullptr) {
      auto keep = v; // the object stays alive while iterating
      std::int64_t n = seq->length();
      for (std::int64_t i = 0; i < n; ++i) {
        if (!f(seq->item(i))) {
          return;
        }
      }
      return;
    }
    langError("LANG_TYPE.7", {{"type_name", v.typeName()}});
  }
}

} // namespace stella
