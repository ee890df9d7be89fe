#pragma once
// The values of the command language: what expressions evaluate to, what commands receive as
// keyword arguments, and what commands return (concepts).
//
// Python semantics: lists and dicts are shared mutable objects (assigning a list does not copy
// it); tuples, strings and numbers are immutable values.

#include "SourceFile.hpp"

#include <complex>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace stella {

class Value;
struct CallArguments;

using ValueList = std::vector<Value>;

// Deepest nesting of containers that printing, comparison and ordering follow (Python's default
// recursion limit); deeper is the user error LANG_DEPTH.
inline constexpr int maxValueNesting = 1000;

// Python's repr() of a string: quoted with ' (or " when it contains ' but no "), with the
// backslash escapes \\, \n, \r, \t and of the quote.
std::string quoteString(const std::string& s);

struct ListObject {
  ValueList items;
};

struct DictObject {
  std::vector<std::pair<Value, Value>> items; // insertion order, unique keys
};

// One keyword of a call or of a factor keyword occurrence `_F(...)`, with the place where the
// user wrote it, so that the catalogue can point at a faulty keyword.
struct KeywordArgument {
  std::string name;
  std::shared_ptr<const Value> value;
  SourceLocation location;      // of the keyword name
  SourceLocation valueLocation; // of the value expression
};

// `_F(K1=v1, K2=v2)`: one occurrence of a factor keyword.
struct FactorObject {
  std::vector<KeywordArgument> keywords;
  SourceLocation location; // of the `_F`
};

// Data owned by the solver behind a concept (a mesh, a model, a result...). The interpreter
// never looks inside.
class ConceptData {
public:
  virtual ~ConceptData() = default;
};

// A named object produced by a command: `MAIL = LIRE_MAILLAGE(...)` makes a concept named MAIL
// of type `maillage`. `data` is null when commands are validated but not executed
// (`stella check`).
struct Concept {
  std::string name;
  std::string type; // catalogue result type: maillage, modele, evol_noli, char_contact...
  std::shared_ptr<ConceptData> data;
  SourceLocation definedAt;
  bool destroyed = false; // after DETRUIRE
};

// Something that can be called from the language: a built-in (`range`, `_F`, `SIMP` in the
// catalogue), a user `def`, or a command (`LIRE_MAILLAGE`).
class Callable {
public:
  virtual ~Callable() = default;
  virtual std::string name() const = 0;
  // Commands are called through the CommandHandler; the evaluator asks this to know whether to
  // pass the assignment target along.
  virtual bool isCommand() const { return false; }
};

// An opaque native object made by a native function (catalogue building blocks, method-bearing
// objects such as a table's EXTR_TABLE result).
class NativeObject {
public:
  virtual ~NativeObject() = default;
  virtual std::string typeName() const = 0;
  // `obj.NAME`: the attribute's value (a NativeCallable for a method), or nullptr when the object
  // has no such attribute (the evaluator then reports LANG_ATTR at the user's location).
  virtual std::shared_ptr<const Value> attribute(const std::string& name) const;
};

struct NoneType {
  bool operator==(const NoneType&) const = default;
};

// A tuple is an immutable sequence; it shares its storage when copied.
struct TupleValue {
  std::shared_ptr<const ValueList> items;
};

class Value {
public:
  enum class Kind {
    None,
    Bool,
    Int,
    Real,
    Complex,
    String,
    Tuple,
    List,
    Dict,
    Factor,
    Concept,
    Callable,
    Native
  };

  Value() = default; // None
  Value(NoneType) {}
  Value(bool b) : v_(b) {}
  Value(int i) : v_(static_cast<std::int64_t>(i)) {}
  Value(std::int64_t i) : v_(i) {}
  Value(double d) : v_(d) {}
  Value(std::complex<double> c) : v_(c) {}
  Value(std::string s) : v_(std::move(s)) {}
  Value(const char* s) : v_(std::string(s)) {}
  Value(TupleValue t) : v_(std::move(t)) {}
  Value(std::shared_ptr<ListObject> l) : v_(std::move(l)) {}
  Value(std::shared_ptr<DictObject> d) : v_(std::move(d)) {}
  Value(std::shared_ptr<FactorObject> f) : v_(std::move(f)) {}
  Value(std::shared_ptr<Concept> c) : v_(std::move(c)) {}
  Value(std::shared_ptr<Callable> c) : v_(std::move(c)) {}
  Value(std::shared_ptr<NativeObject> n) : v_(std::move(n)) {}

  // Freeing a value frees the containers only it holds without recursion, so that a list
  // nested 100000 deep (built in a loop) cannot exhaust the stack; assignment frees the old
  // content the same way.
  ~Value() {
    if (holdsContainer()) {
      releaseContainer();
    }
  }
  Value(const Value&) = default;
  Value(Value&&) noexcept = default;
  Value& operator=(const Value& other);
  Value& operator=(Value&& other) noexcept;

  static Value tuple(ValueList items) {
    return Value(TupleValue{std::make_shared<const ValueList>(std::move(items))});
  }
  static Value list(ValueList items) {
    return Value(std::make_shared<ListObject>(ListObject{std::move(items)}));
  }

  Kind kind() const { return static_cast<Kind>(v_.index()); }
  bool isNone() const { return kind() == Kind::None; }
  bool isBool() const { return kind() == Kind::Bool; }
  bool isInt() const { return kind() == Kind::Int; }
  bool isReal() const { return kind() == Kind::Real; }
  bool isNumber() const { return isInt() || isReal() || isBool(); }
  bool isString() const { return kind() == Kind::String; }
  bool isTuple() const { return kind() == Kind::Tuple; }
  bool isList() const { return kind() == Kind::List; }
  bool isSequence() const { return isTuple() || isList(); }
  bool isDict() const { return kind() == Kind::Dict; }
  bool isFactor() const { return kind() == Kind::Factor; }
  bool isConcept() const { return kind() == Kind::Concept; }
  bool isCallable() const { return kind() == Kind::Callable; }
  bool isNative() const { return kind() == Kind::Native; }

  bool asBool() const { return std::get<bool>(v_); }
  std::int64_t asInt() const { return isBool() ? (asBool() ? 1 : 0) : std::get<std::int64_t>(v_); }
  double asReal() const; // int, bool or real
  std::complex<double> asComplex() const { return std::get<std::complex<double>>(v_); }
  const std::string& asString() const { return std::get<std::string>(v_); }
  // Items of a tuple or a list.
  const ValueList& items() const;
  const std::shared_ptr<ListObject>& asList() const { return std::get<std::shared_ptr<ListObject>>(v_); }
  const std::shared_ptr<DictObject>& asDict() const { return std::get<std::shared_ptr<DictObject>>(v_); }
  const std::shared_ptr<FactorObject>& asFactor() const {
    return std::get<std::shared_ptr<FactorObject>>(v_);
  }
  const std::shared_ptr<Concept>& asConcept() const { return std::get<std::shared_ptr<Concept>>(v_); }
  const std::shared_ptr<Callable>& asCallable() const { return std::get<std::shared_ptr<Callable>>(v_); }
  const std::shared_ptr<NativeObject>& asNative() const {
    return std::get<std::shared_ptr<NativeObject>>(v_);
  }

  // Python's truth value.
  bool truthy() const;
  // Python's repr() (strings quoted) and str() (strings bare).
  std::string repr() const;
  std::string str() const;
  // The Python type name used in messages: 'int', 'float', 'str', 'tuple', '_F', or the
  // concept's catalogue type.
  std::string typeName() const;
  // Python equality (1 == 1.0, tuples element-wise, concepts by identity). Containers nested
  // deeper than maxValueNesting (or cyclic ones that are not identical) throw a UserError
  // LANG_DEPTH without location, like repr().
  bool equals(const Value& other) const;

private:
  bool holdsContainer() const {
    auto k = kind();
    return k == Kind::Tuple || k == Kind::List || k == Kind::Dict || k == Kind::Factor;
  }
  bool soleOwnerOfContainer() const;
  void releaseContainer() noexcept;

  std::variant<NoneType, bool, std::int64_t, double, std::complex<double>, std::string, TupleValue,
               std::shared_ptr<ListObject>, std::shared_ptr<DictObject>, std::shared_ptr<FactorObject>,
               std::shared_ptr<Concept>, std::shared_ptr<Callable>, std::shared_ptr<NativeObject>>
      v_;
};

// The arguments of one call, with where each was written.
struct CallArguments {
  std::vector<Value> positional;
  std::vector<SourceLocation> positionalLocations;
  std::vector<KeywordArgument> keywords; // in the order written, `**dict` expanded
  SourceLocation callLocation;           // of the callee name
  SourceLocation closeLocation;          // of the closing parenthesis

  const KeywordArgument* find(const std::string& name) const;
};

// A function implemented in C++ (built-ins, catalogue building blocks, math).
using NativeFunction = std::function<Value(const CallArguments&)>;

// A Callable implemented by a NativeFunction: what defineNative binds, what a handler returns
// for a concept method (`TAB.EXTR_TABLE`) or for calling a concept (`conceptAttribute(c,
// "__call__")`, e.g. a FORMULE). A UserError it throws without a location gets the call's.
class NativeCallable : public Callable {
public:
  NativeCallable(std::string name, NativeFunction fn) : name_(std::move(name)), fn_(std::move(fn)) {}
  std::string name() const override { return name_; }
  const NativeFunction& function() const { return fn_; }

private:
  std::string name_;
  NativeFunction fn_;
};

// Value holding a NativeCallable.
Value makeNativeFunction(std::string name, NativeFunction fn);

} // namespace stella
