// The language's values: truth, equality, repr/str and type names with Python's rules.
#include "Value.hpp"

#include "Diagnostics.hpp"
#include "Exceptions.hpp"
#include "StringEscape.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella {

std::shared_ptr<const Value> NativeObject::attribute(const std::string& /*name*/) const {
  return nullptr;
}

Value makeNativeFunction(std::string name, NativeFunction fn) {
  return Value(std::shared_ptr<Callable>(std::make_shared<NativeCallable>(std::move(name), std::move(fn))));
}

double Value::asReal() const {
  switch (kind()) {
  case Kind::Real:
    return std::get<double>(v_);
  case Kind::Int:
    return static_cast<double>(std::get<std::int64_t>(v_));
  case Kind::Bool:
    return std::get<bool>(v_) ? 1.0 : 0.0;
  default:
    STELLA_ASSERT(false, "asReal() on a " + typeName());
  }
  return 0.0;
}

const ValueList& Value::items() const {
  if (isTuple()) {
    return *std::get<TupleValue>(v_).items;
  }
  STELLA_ASSERT(isList(), "items() on a " + typeName());
  return asList()->items;
}

bool Value::truthy() const {
  switch (kind()) {
  case Kind::None:
    return false;
  case Kind::Bool:
    return asBool();
  case Kind::Int:
    return asInt() != 0;
  case Kind::Real:
    return asReal() != 0.0;
  case Kind::Complex:
    return asComplex() != std::complex<double>(0.0, 0.0);
  case Kind::String:
    return !asString().empty();
  case Kind::Tuple:
  case Kind::List:
    return !items().empty();
  case Kind::Dict:
    return !asDict()->items.empty();
  default:
    return true;
  }
}

namespace {

std::string formatReal(double d) {
  if (std::isnan(d)) {
    return "nan";
  }
  if (std::isinf(d)) {
    return d > 0 ? "inf" : "-inf";
  }
  std::string s = fmt::format("{}", d);
  if (s.find_first_of(".e") == std::string::npos) {
    s += ".0";
  }
  return s;
}

} // namespace

std::string quoteString(const std::string& s) {
  char q = (s.find('\'') != std::string::npos && s.find('"') == std::string::npos) ? '"' : '\'';
  return quoted(s, q, EscapeStyle::Python);
}

namespace {

[[noreturn]] void tooDeep(const char* what) {
  throw UserError(
      msg::make("LANG_DEPTH", {{"what", what}, {"max_value_nesting", std::to_string(maxValueNesting)}}));
}

// Containers being printed, to print a list that contains itself as [...] like Python.
using Visiting = std::vector<const void*>;

std::string reprOf(const Value& v, Visiting& visiting);

std::string reprSequence(const ValueList& items, const char* open, const char* close, bool tuple,
                         Visiting& visiting) {
  std::string out = open;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) {
      out += ", ";
    }
    out += reprOf(items[i], visiting);
  }
  if (tuple && items.size() == 1) {
    out += ",";
  }
  out += close;
  return out;
}

std::string reprOf(const Value& v, Visiting& visiting) {
  using K = Value::Kind;
  if (visiting.size() >= static_cast<std::size_t>(maxValueNesting) &&
      (v.isSequence() || v.isDict() || v.isFactor())) {
    tooDeep("print");
  }
  switch (v.kind()) {
  case K::None:
    return "None";
  case K::Bool:
    return v.asBool() ? "True" : "False";
  case K::Int:
    return std::to_string(v.asInt());
  case K::Real:
    return formatReal(v.asReal());
  case K::Complex: {
    auto c = v.asComplex();
    return "(" + formatReal(c.real()) + (c.imag() < 0 ? "-" : "+") + formatReal(std::abs(c.imag())) + "j)";
  }
  case K::String:
    return quoteString(v.asString());
  case K::Tuple: {
    visiting.push_back(nullptr); // depth marker (tuples cannot contain themselves)
    std::string out = reprSequence(v.items(), "(", ")", true, visiting);
    visiting.pop_back();
    return out;
  }
  case K::List: {
    const void* id = v.asList().get();
    if (std::find(visiting.begin(), visiting.end(), id) != visiting.end()) {
      return "[...]";
    }
    visiting.push_back(id);
    std::string out = reprSequence(v.items(), "[", "]", false, visiting);
    visiting.pop_back();
    return out;
  }
  case K::Dict: {
    const void* id = v.asDict().get();
    if (std::find(visiting.begin(), visiting.end(), id) != visiting.end()) {
      return "{...}";
    }
    visiting.push_back(id);
    std::string out = "{";
    bool first = true;
    for (const auto& [key, value] : v.asDict()->items) {
      if (!first) {
        out += ", ";
      }
      first = false;
      out += reprOf(key, visiting) + ": " + reprOf(value, visiting);
    }
    visiting.pop_back();
    return out + "}";
  }
  case K::Factor: {
    visiting.push_back(nullptr);
    std::string out = "_F(";
    bool first = true;
    for (const auto& kw : v.asFactor()->keywords) {
      if (!first) {
        out += ", ";
      }
      first = false;
      out += kw.name + "=" + (kw.value ? reprOf(*kw.value, visiting) : "None");
    }
    visiting.pop_back();
    return out + ")";
  }
  case K::Concept:
    return v.asConcept()->name;
  case K::Callable:
    return "<" + std::string(v.asCallable()->isCommand() ? "command " : "function ") +
           v.asCallable()->name() + ">";
  case K::Native:
    if (const auto* e = dynamic_cast<const ExceptionObject*>(v.asNative().get())) {
      return e->reprText();
    }
    return "<" + v.asNative()->typeName() + ">";
  }
  return "?";
}

bool equalsAt(const Value& a, const Value& b, int depth);

bool checkedDepth(int depth) {
  if (depth >= maxValueNesting) {
    tooDeep("compare");
  }
  return true;
}

bool sequencesEqual(const ValueList& a, const ValueList& b, int depth) {
  if (a.size() != b.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!equalsAt(a[i], b[i], depth + 1)) {
      return false;
    }
  }
  return true;
}

bool dictsEqual(const DictObject& a, const DictObject& b, int depth) {
  if (a.items.size() != b.items.size()) {
    return false;
  }
  for (const auto& entry : a.items) {
    const Value& key = entry.first;
    auto it = std::find_if(b.items.begin(), b.items.end(),
                           [&](const auto& other) { return equalsAt(other.first, key, depth + 1); });
    if (it == b.items.end() || !equalsAt(it->second, entry.second, depth + 1)) {
      return false;
    }
  }
  return true;
}

bool equalsAt(const Value& a, const Value& b, int depth) {
  using K = Value::Kind;
  if (a.isNumber() && b.isNumber()) {
    if (a.isReal() || b.isReal()) {
      return a.asReal() == b.asReal();
    }
    return a.asInt() == b.asInt();
  }
  if (a.kind() == K::Complex || b.kind() == K::Complex) {
    auto toComplex = [](const Value& v) {
      return v.kind() == K::Complex ? v.asComplex() : std::complex<double>(v.asReal(), 0.0);
    };
    if ((a.kind() == K::Complex || a.isNumber()) && (b.kind() == K::Complex || b.isNumber())) {
      return toComplex(a) == toComplex(b);
    }
    return false;
  }
  if (a.kind() != b.kind()) {
    return false;
  }
  switch (a.kind()) {
  case K::None:
    return true;
  case K::String:
    return a.asString() == b.asString();
  case K::Tuple:
    return checkedDepth(depth) && sequencesEqual(a.items(), b.items(), depth);
  case K::List:
    return a.asList() == b.asList() || (checkedDepth(depth) && sequencesEqual(a.items(), b.items(), depth));
  case K::Dict:
    return a.asDict() == b.asDict() || (checkedDepth(depth) && dictsEqual(*a.asDict(), *b.asDict(), depth));
  case K::Factor:
    return a.asFactor() == b.asFactor();
  case K::Concept:
    return a.asConcept() == b.asConcept();
  case K::Callable:
    return a.asCallable() == b.asCallable();
  case K::Native:
    return a.asNative() == b.asNative();
  default:
    return false;
  }
}

} // namespace

Value& Value::operator=(const Value& other) {
  if (this != &other) {
    Value old(std::move(*this)); // keeps `other` alive if it is inside the old content
    v_ = other.v_;
  }
  return *this;
}

Value& Value::operator=(Value&& other) noexcept {
  if (this != &other) {
    Value old(std::move(*this));
    v_ = std::move(other.v_);
  }
  return *this;
}

bool Value::soleOwnerOfContainer() const {
  switch (kind()) {
  case Kind::Tuple:
    return std::get<TupleValue>(v_).items.use_count() == 1;
  case Kind::List:
    return asList().use_count() == 1;
  case Kind::Dict:
    return asDict().use_count() == 1;
  case Kind::Factor:
    return asFactor().use_count() == 1;
  default:
    return false;
  }
}

// Values whose container is to be freed by the outermost releaseContainer() on this thread.
namespace {
thread_local std::vector<Value>* pendingRelease = nullptr;
}

void Value::releaseContainer() noexcept {
  if (!soleOwnerOfContainer()) {
    return; // another value still holds it (or it is a moved-from empty pointer)
  }
  if (pendingRelease != nullptr) {
    try {
      pendingRelease->push_back(std::move(*this)); // freed later by the loop below
    } catch (...) {
      // out of memory: free it here, recursively
    }
    return;
  }
  std::vector<Value> pending;
  pendingRelease = &pending;
  v_ = NoneType{}; // frees this container; the containers it solely held are queued in `pending`
  while (!pending.empty()) {
    Value next = std::move(pending.back());
    pending.pop_back();
    next.v_ = NoneType{};
  }
  pendingRelease = nullptr;
}

std::string Value::repr() const {
  Visiting visiting;
  return reprOf(*this, visiting);
}

std::string Value::str() const {
  if (isString()) {
    return asString();
  }
  if (isNative()) {
    if (const auto* e = dynamic_cast<const ExceptionObject*>(asNative().get())) {
      return e->strText();
    }
  }
  return repr();
}

std::string Value::typeName() const {
  switch (kind()) {
  case Kind::None:
    return "NoneType";
  case Kind::Bool:
    return "bool";
  case Kind::Int:
    return "int";
  case Kind::Real:
    return "float";
  case Kind::Complex:
    return "complex";
  case Kind::String:
    return "str";
  case Kind::Tuple:
    return "tuple";
  case Kind::List:
    return "list";
  case Kind::Dict:
    return "dict";
  case Kind::Factor:
    return "_F";
  case Kind::Concept:
    return asConcept()->type;
  case Kind::Callable:
    return asCallable()->isCommand() ? "command" : "function";
  case Kind::Native:
    return asNative()->typeName();
  }
  return "?";
}

bool Value::equals(const Value& other) const {
  return equalsAt(*this, other, 0);
}

const KeywordArgument* CallArguments::find(const std::string& name) const {
  for (const auto& kw : keywords) {
    if (kw.name == name) {
      return &kw;
    }
  }
  return nullptr;
}

} // namespace stella
