#pragma once
// The errors a command file can catch with `try`/`except` and raise with `raise`: Python's
// exception classes the language's own errors map to, and code_aster's (AsterError and its
// subclasses) so that files naming them run. See doc/language.md, "Errors and try/except".

#include "Diagnostics.hpp"
#include "Value.hpp"

#include <memory>
#include <string>
#include <unordered_map>

namespace stella {

// An exception class (`ValueError`): calling it makes an ExceptionObject.
class ExceptionClass : public NativeCallable {
public:
  ExceptionClass(std::string name, const ExceptionClass* parent);
  const ExceptionClass* parent() const { return parent_; }
  // True when this class is `other` or derives from it.
  bool isSubclassOf(const ExceptionClass& other) const;

private:
  const ExceptionClass* parent_;
};

// An exception (`ValueError('bad value')`): its class and its arguments.
class ExceptionObject : public NativeObject {
public:
  ExceptionObject(std::shared_ptr<const ExceptionClass> cls, ValueList args)
      : class_(std::move(cls)), args_(std::move(args)) {}
  std::string typeName() const override { return class_->name(); }
  std::shared_ptr<const Value> attribute(const std::string& name) const override;
  std::string strText() const;  // str(e): the message
  std::string reprText() const; // repr(e): ValueError('message')
  const ExceptionClass& exceptionClass() const { return *class_; }

private:
  std::shared_ptr<const ExceptionClass> class_;
  ValueList args_;
};

// An error on its way up through the evaluator with what `except` needs to know: whether it
// comes from a command (its operator or its catalogue check: never caught) and the exception
// object of a `raise`.
class TracedError : public UserError {
public:
  TracedError(const UserError& error, bool fromCommand, std::shared_ptr<const ExceptionObject> raised)
      : UserError(error.diagnostics()), fromCommand_(fromCommand), raised_(std::move(raised)) {}
  bool fromCommand() const { return fromCommand_; }
  const std::shared_ptr<const ExceptionObject>& raised() const { return raised_; }

private:
  bool fromCommand_;
  std::shared_ptr<const ExceptionObject> raised_;
};

// Throws `error` again with other diagnostics (a location or a note added on the way up),
// keeping what a TracedError knows.
[[noreturn]] void rethrowWith(const UserError& error, std::vector<Diagnostic> diagnostics);

// The exception classes every command file sees, by name.
const std::unordered_map<std::string, Value>& exceptionNames();
// The class of one of them (nullptr when there is no such class).
std::shared_ptr<const ExceptionClass> findExceptionClass(const std::string& name);
// The exception an error stands for when `except` looks at it: the object of a `raise`, or the
// Python class of a language error (LANG_ZERO is ZeroDivisionError...). nullptr for errors that
// cannot be caught: errors of commands, and the sandbox's limits (LANG_DEPTH, LANG_WHILE...).
std::shared_ptr<const ExceptionObject> caughtException(const UserError& error);

} // namespace stella
