// The exception classes of the language (Python's and code_aster's), the exception objects made
// by calling them, and which errors `except` can catch.
#include "Exceptions.hpp"

#include "Runtime.hpp"

#include <map>
#include <utility>
#include <vector>

namespace stella {

ExceptionClass::ExceptionClass(std::string name, const ExceptionClass* parent)
    : NativeCallable(name,
                     [this, name](const CallArguments& a) -> Value {
                       if (!a.keywords.empty()) {
                         langError("LANG_ARGS.9", {{"name", name}, {"name_2", a.keywords[0].name}});
                       }
                       // `this` lives as long as the class table, which outlives every call
                       auto self = findExceptionClass(this->name());
                       return Value(std::shared_ptr<NativeObject>(
                           std::make_shared<ExceptionObject>(self, a.positional)));
                     }),
      parent_(parent) {}

bool ExceptionClass::isSubclassOf(const ExceptionClass& other) const {
  for (const ExceptionClass* c = this; c != nullptr; c = c->parent_) {
    if (c == &other) {
      return true;
    }
  }
  return false;
}

std::shared_ptr<const Value> ExceptionObject::attribute(const std::string& name) const {
  if (name == "args") {
    return std::make_shared<const Value>(Value::tuple(args_));
  }
  return nullptr;
}

// Python's str(e): '' without arguments, str(arg) with one, the tuple's repr with several.
std::string ExceptionObject::strText() const {
  if (args_.empty()) {
    return "";
  }
  if (args_.size() == 1) {
    return args_[0].str();
  }
  return Value::tuple(args_).repr();
}

std::string ExceptionObject::reprText() const {
  std::string out = class_->name() + "(";
  for (std::size_t i = 0; i < args_.size(); ++i) {
    out += (i > 0 ? ", " : "") + args_[i].repr();
  }
  return out + ")";
}

namespace {

struct ExceptionTable {
  std::map<std::string, std::shared_ptr<const ExceptionClass>> classes;
  std::unordered_map<std::string, Value> names;

  const ExceptionClass* add(const std::string& name, const ExceptionClass* parent) {
    auto cls = std::make_shared<const ExceptionClass>(name, parent);
    classes[name] = cls;
    names.emplace(name, Value(std::shared_ptr<Callable>(std::const_pointer_cast<ExceptionClass>(cls))));
    return cls.get();
  }
};

const ExceptionTable& table() {
  static const ExceptionTable instance = [] {
    ExceptionTable t;
    const ExceptionClass* base = t.add("Exception", nullptr);
    const ExceptionClass* arithmetic = t.add("ArithmeticError", base);
    t.add("ZeroDivisionError", arithmetic);
    t.add("OverflowError", arithmetic);
    const ExceptionClass* lookup = t.add("LookupError", base);
    t.add("IndexError", lookup);
    t.add("KeyError", lookup);
    t.add("NameError", base);
    t.add("TypeError", base);
    t.add("ValueError", base);
    t.add("AttributeError", base);
    t.add("AssertionError", base);
    t.add("ImportError", base);
    const ExceptionClass* runtime = t.add("RuntimeError", base);
    t.add("NotImplementedError", runtime);
    // never raised (files cannot reach the file system), named by `except OSError:` clauses
    const ExceptionClass* os = t.add("OSError", base);
    t.add("FileNotFoundError", os);
    t.classes["IOError"] = t.classes.at("OSError"); // Python 3: one class, two names
    t.names.emplace("IOError", t.names.at("OSError"));
    // code_aster's errors (code_aster.AsterError and its subclasses): named by real files
    const ExceptionClass* aster = t.add("AsterError", base);
    for (const char* name :
         {"ConvergenceError", "IntegrationError", "SolverError", "ContactError", "TimeLimitError"}) {
      t.add(name, aster);
    }
    return t;
  }();
  return instance;
}

// The language's errors that `except` catches, with their Python class.
const char* classOfErrorId(const std::string& id) {
  static const std::map<std::string, const char*> classes = {
      {"LANG_ZERO", "ZeroDivisionError"}, {"LANG_KEY", "KeyError"},          {"LANG_INDEX", "IndexError"},
      {"LANG_NAME", "NameError"},         {"LANG_TYPE", "TypeError"},        {"LANG_CALL", "TypeError"},
      {"LANG_ARGS", "TypeError"},         {"LANG_VALUE", "ValueError"},      {"LANG_ATTR", "AttributeError"},
      {"CONCEPT_1", "AttributeError"},    {"LANG_ASSERT", "AssertionError"}, {"LANG_IMPORT", "ImportError"},
      {"LANG_OVERFLOW", "OverflowError"},
  };
  auto it = classes.find(id);
  return it == classes.end() ? nullptr : it->second;
}

} // namespace

const std::unordered_map<std::string, Value>& exceptionNames() {
  return table().names;
}

std::shared_ptr<const ExceptionClass> findExceptionClass(const std::string& name) {
  auto it = table().classes.find(name);
  return it == table().classes.end() ? nullptr : it->second;
}

void rethrowWith(const UserError& error, std::vector<Diagnostic> diagnostics) {
  if (const auto* traced = dynamic_cast<const TracedError*>(&error)) {
    throw TracedError(UserError(std::move(diagnostics)), traced->fromCommand(), traced->raised());
  }
  throw UserError(std::move(diagnostics));
}

std::shared_ptr<const ExceptionObject> caughtException(const UserError& error) {
  if (const auto* traced = dynamic_cast<const TracedError*>(&error)) {
    if (traced->raised()) {
      return traced->raised();
    }
    if (traced->fromCommand()) {
      return nullptr;
    }
  }
  const char* name = classOfErrorId(error.first().id);
  if (name == nullptr) {
    return nullptr;
  }
  return std::make_shared<const ExceptionObject>(findExceptionClass(name),
                                                 ValueList{Value(error.first().message)});
}

} // namespace stella
