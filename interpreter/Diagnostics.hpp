#pragma once
// User-facing diagnostics: every message a user sees has a severity, a message id (tests assert
// on ids, not prose), a location in the command file, the message and optional notes.
//
// Two channels (DESIGN §8.4): UserError carries a Diagnostic about the user's input and is
// reported as `file:line:col: error: ...`; STELLA_ASSERT is for internal invariants and names
// the C++ location, for developers.

#include "SourceFile.hpp"

#include <exception>
#include <string>
#include <vector>

namespace stella {

// code_aster's message classes: <I> information, <A> alarm, <F> fatal error, <S> exception
// (an error after which the results computed so far are kept, e.g. no convergence).
enum class Severity { Info, Alarm, Fatal, Exception };

// What kind of failure a fatal diagnostic is; drives the job diagnostic word.
enum class FailureKind {
  None,          // informations and alarms
  Syntax,        // command language or catalogue validation: <F>_SYNTAX_ERROR
  Error,         // any other user error: <F>_ERROR
  NoConvergence, // <S>_NO_CONVERGENCE
  Abort,         // internal error: <F>_ABNORMAL_ABORT
  Interrupted    // a signal or the time limit stopped the run at a safe point: <S>_INTERRUPTED
};

struct Diagnostic {
  Severity severity = Severity::Fatal;
  FailureKind kind = FailureKind::Error;
  std::string id;      // e.g. SYNTAX_1, CATALOG_3, MESH_2
  std::string message; // one sentence, no trailing newline
  SourceLocation location;
  std::vector<std::string> notes;

  static Diagnostic info(std::string id, std::string message, SourceLocation at = {});
  static Diagnostic alarm(std::string id, std::string message, SourceLocation at = {});
  static Diagnostic fatal(std::string id, std::string message, SourceLocation at = {});
  static Diagnostic syntax(std::string id, std::string message, SourceLocation at = {});
  static Diagnostic noConvergence(std::string id, std::string message, SourceLocation at = {});

  Diagnostic&& withNote(std::string note) &&;
  Diagnostic& withNote(std::string note) &;
  Diagnostic&& at(SourceLocation where) &&;
};

// "file:line:col: error: message [ID]" then the source line, a caret line under the located
// token, then "note: ..." lines. Locations without a file print the message alone.
std::string formatDiagnostic(const Diagnostic& d);
// The code_aster-style letter of a severity: "<I>", "<A>", "<F>", "<S>".
const char* severityTag(Severity s);

// Thrown for an error in the user's input. Carries one or more diagnostics (a command's
// catalogue errors are all reported at once).
class UserError : public std::exception {
public:
  explicit UserError(Diagnostic d) { diagnostics_.push_back(std::move(d)); }
  explicit UserError(std::vector<Diagnostic> ds) : diagnostics_(std::move(ds)) {}
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  const Diagnostic& first() const { return diagnostics_.front(); }
  const char* what() const noexcept override { return diagnostics_.front().message.c_str(); }

private:
  std::vector<Diagnostic> diagnostics_;
};

// Receives diagnostics that do not stop the run (alarms, infos) and the ones that do, for
// display. The session's sink writes them to the message file and counts them.
class DiagnosticSink {
public:
  virtual ~DiagnosticSink() = default;
  virtual void report(const Diagnostic& d) = 0;
};

// Internal invariant violated: a bug in stella, not in the user's input.
class InternalError : public std::exception {
public:
  InternalError(std::string message, const char* file, int line);
  const char* what() const noexcept override { return text_.c_str(); }

private:
  std::string text_;
};

} // namespace stella

#define STELLA_ASSERT(cond, msg)                                                                             \
  do {                                                                                                       \
    if (!(cond)) {                                                                                           \
      throw ::stella::InternalError(std::string("assertion '" #cond "' failed: ") + (msg), __FILE__,         \
                                    __LINE__);                                                               \
    }                                                                                                        \
  } while (false)
