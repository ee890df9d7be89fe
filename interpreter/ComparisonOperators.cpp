// Comparison operators with Python's rules: ==, !=, ordering of numbers, strings and sequences,
// membership (in, not in) and identity (is, is not).
#include "Runtime.hpp"
#include "SequenceObject.hpp"

#include <algorithm>
#include <cmath>

namespace stella {

namespace {

using K = Value::Kind;

bool isIntLike(const Value& v) {
  return v.isInt() || v.isBool();
}

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
      langError("LANG_DEPTH.2", {{"max_value_nesting", std::to_string(maxValueNesting)}});
    }
    return compareSequences(a.items(), b.items(), depth);
  }
  langError("LANG_TYPE.20", {{"type_name", a.typeName()}, {"type_name_2", b.typeName()}});
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
      langError("LANG_TYPE.21", {{"type_name", item.typeName()}});
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
  langError("LANG_TYPE.22", {{"type_name", container.typeName()}});
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

} // namespace stella
