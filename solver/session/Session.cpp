#include "Session.hpp"

#include "ConceptMethods.hpp"
#include "OperatorRegistry.hpp"
#include "catalog/Catalog.hpp"
#include "catalog/CommandSpec.hpp"
#include "interpreter/Suggest.hpp"
#include "messages/Messages.hpp"
#include "solver/database/Result.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/io/ResultWriters.hpp"
#include "solver/io/RigiPoints.hpp"
#include "solver/session/ExceptionDiagnostic.hpp"
#include "solver/session/StopRequest.hpp"

#include <algorithm>
#include <optional>

#include <ctime>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sstream>

namespace stella {

namespace {

// F(1.5) or F(X=1.5, Y=2.0) in a command file: a FORMULE or a DEFI_FONCTION evaluated with its
// parameters given by position (in NOM_PARA order) or by name.
double callRealFunction(const RealFunction& function, const std::string& name, const CallArguments& args) {
  const std::vector<std::string> parameters = function.parameters();
  std::vector<std::optional<double>> values(parameters.size());
  auto fail = [&](const std::string& message) {
    return UserError(msg::make("FUNCTION_11",
                               {{"name", name}, {"message", message}, {"join", fmt::join(parameters, ", ")}},
                               args.callLocation));
  };
  if (args.positional.size() > parameters.size()) {
    throw fail(
        msg::text("FUNCTION_11.count", {{"count", parameters.size()}, {"given", args.positional.size()}}));
  }
  for (std::size_t i = 0; i < args.positional.size(); ++i) {
    if (!args.positional[i].isNumber()) {
      throw fail(msg::text("FUNCTION_11.type",
                           {{"parameter", parameters[i]}, {"type", args.positional[i].typeName()}}));
    }
    values[i] = args.positional[i].asReal();
  }
  for (const KeywordArgument& k : args.keywords) {
    const auto it = std::find(parameters.begin(), parameters.end(), k.name);
    if (it == parameters.end()) {
      throw fail(msg::text("FUNCTION_11.unknown", {{"parameter", k.name}}));
    }
    auto& slot = values[static_cast<std::size_t>(it - parameters.begin())];
    if (slot || !k.value->isNumber()) {
      throw fail(slot ? msg::text("FUNCTION_11.twice", {{"parameter", k.name}})
                      : msg::text("FUNCTION_11.number", {{"parameter", k.name}}));
    }
    slot = k.value->asReal();
  }
  std::vector<double> given;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!values[i]) {
      throw fail(msg::text("FUNCTION_11.missing", {{"parameter", parameters[i]}}));
    }
    given.push_back(*values[i]);
  }
  return function.evaluate(given);
}

// Operators that read no file, write nothing and cost next to nothing: `stella check` runs them
// too, so that FIN() ends the file, a FORMULE's expression is compiled (its errors point inside
// the string) and functions and lists can be called or read later in the file.
constexpr int frameWidth = 80;

std::string frameLine(const std::string& text) {
  std::string line = " ! " + text;
  if (line.size() < frameWidth - 1) {
    line.append(frameWidth - 1 - line.size(), ' ');
  }
  return line + "!\n";
}

std::string frameRule() {
  return " !" + std::string(frameWidth - 3, '-') + "!\n";
}

// The located diagnostic as lines inside a code_aster-style frame, so that tools reading the
// message file (regexes on "<A>", "<F>"...) and users see the same thing.
std::string framed(const Diagnostic& d) {
  std::string out = frameRule();
  out += frameLine(std::string(severityTag(d.severity)) + " <" + d.id + ">");
  std::istringstream body(formatDiagnostic(d));
  std::string line;
  while (std::getline(body, line)) {
    out += frameLine(line);
  }
  out += frameRule();
  return out;
}

// Diagnostics thrown by the catalogue's validation are syntax errors of the command file.
UserError asSyntax(const UserError& e) {
  std::vector<Diagnostic> ds = e.diagnostics();
  for (auto& d : ds) {
    // CATALOG_17 (not implemented yet) is stella's limit, not the user's mistake: <F>_ERROR.
    if (d.severity == Severity::Fatal && d.kind == FailureKind::Error && d.id != "CATALOG_17") {
      d.kind = FailureKind::Syntax;
    }
  }
  return UserError(std::move(ds));
}

std::string callHeader(const std::string& target, const std::string& command) {
  return target.empty() ? command + "(" : target + " = " + command + "(";
}

// An error an operator reports elsewhere than in its own call (a FORMULE it evaluates, defined
// earlier in the file) also names the command that was running.
UserError withCallingCommand(const UserError& e, const std::string& command, const CallArguments& args) {
  std::vector<Diagnostic> ds = e.diagnostics();
  const SourceLocation& call = args.callLocation;
  const int lastLine = args.closeLocation.known() ? args.closeLocation.line : call.line;
  for (auto& d : ds) {
    const bool inCall =
        d.location.file == call.file && d.location.line >= call.line && d.location.line <= lastLine;
    if (call.known() && !inCall) {
      d.withNote(msg::text("NOTE.n3", {{"command", command}, {"call", call.str()}}));
    }
  }
  return UserError(std::move(ds));
}

} // namespace

std::string framedDiagnostic(const Diagnostic& d) {
  return framed(d);
}

Session::Session(const Catalog& catalog, std::ostream& message, std::ostream& result, SessionOptions options)
    : catalog_(catalog), message_(message), result_(result), options_(std::move(options)) {}

Session::~Session() = default;

void Session::declareUnit(int unit, std::filesystem::path path) {
  units_[unit] = std::move(path);
}

void Session::declareUnitOrigin(int unit, std::filesystem::path userFile) {
  unitOrigins_[unit] = std::move(userFile);
}

UserError Session::withUserPaths(const UserError& e) const {
  std::vector<Diagnostic> ds = e.diagnostics();
  auto rewrite = [&](std::string& text) {
    for (const auto& [unit, origin] : unitOrigins_) {
      auto it = units_.find(unit);
      if (it == units_.end()) {
        continue;
      }
      const std::string copy = it->second.string();
      const std::string shown = origin.string() + " (unit " + std::to_string(unit) + ")";
      for (std::size_t at = text.find(copy); at != std::string::npos;
           at = text.find(copy, at + shown.size())) {
        text.replace(at, copy.size(), shown);
      }
    }
  };
  for (auto& d : ds) {
    rewrite(d.message);
    for (auto& note : d.notes) {
      rewrite(note);
    }
  }
  return UserError(std::move(ds));
}

std::filesystem::path Session::unitPath(int unit, const SourceLocation& at, bool forReading) const {
  auto it = units_.find(unit);
  std::filesystem::path path =
      it != units_.end() ? it->second : options_.workDirectory / ("fort." + std::to_string(unit));
  if (forReading) {
    if (!std::filesystem::exists(path)) {
      std::string declared;
      for (const auto& [u, p] : units_) {
        declared += (declared.empty() ? "" : ", ") + std::to_string(u) + " (" + p.filename().string() + ")";
      }
      throw UserError(msg::make("UNIT_1", {{"unit", unit}}, at)
                          .withNote(declared.empty() ? msg::text("UNIT_1.n2")
                                                     : msg::text("UNIT_1.n3", {{"declared", declared}}))
                          .withNote(msg::text("UNIT_1.n1", {{"unit", unit}})));
    }
  }
  opened_.push_back(unit);
  return path;
}

void Session::reportDeferred() {
  const auto pending = std::move(deferred_);
  deferred_.clear();
  for (const auto& r : pending) {
    for (const auto& d : r->diagnostics()) {
      report(d);
    }
  }
}

void Session::report(const Diagnostic& d) {
  if (d.severity == Severity::Info) {
    message_ << d.message << '\n';
    return;
  }
  if (d.severity == Severity::Alarm) {
    ++counts_.alarms;
  } else {
    noteFailure(d.kind);
  }
  message_ << framed(d);
}

void Session::writeTestLines(const std::string& text) {
  result_ << text;
  message_ << text;
}

void Session::recordTest(bool ok) {
  ++(ok ? counts_.testsOk : counts_.testsNook);
}

void Session::noteFailure(FailureKind kind) {
  if (counts_.failure == FailureKind::None && kind != FailureKind::None) {
    counts_.failure = kind;
  }
}

Value Session::callCommandOnce(const std::string& command, const CallArguments& args,
                               const std::string& target) {
  ValidatedCall call;
  try {
    call = catalog_.validate(command, args);
  } catch (const UserError& e) {
    throw asSyntax(e);
  }
  OperatorFunction op = OperatorRegistry::instance().find(command);
  if (op == nullptr) {
    // The catalogue marks the command non_implemente= (a unit test holds the two in step).
    const CommandSpec* spec = catalog_.find(command);
    Diagnostic d = msg::make("COMMAND_1", {{"command", command}}, args.callLocation);
    if (spec != nullptr && spec->notImplemented && !spec->notImplemented->empty()) {
      d.withNote(*spec->notImplemented);
    }
    throw UserError(std::move(d));
  }

  const bool execute = options_.executeOperators || runsInCheck(command, call.keywords);
  if (stopRequested() && execute) {
    throw UserError(stopDiagnostic("before " + command, args.callLocation));
  }
  try {
    checkOutputUnit(command, call.keywords, args.callLocation);
  } catch (const UserError& e) {
    throw asSyntax(e);
  }

  ++commandCount_;
  const std::string location = args.callLocation.str();
  message_ << "\n  # " << std::string(70, '-') << "\n"
           << fmt::format("  # Command #{:04d}   {}   ({})\n", commandCount_, command, location);
  if (!call.resultType.empty()) {
    message_ << "  # Result: concept of type " << call.resultType << "\n";
  }
  message_ << "  " << callHeader(target, command) << "\n" << call.keywords.format(6) << "  )\n" << std::flush;

  std::shared_ptr<Concept> made;
  Value result;
  auto wallStart = std::chrono::steady_clock::now();
  std::clock_t cpuStart = std::clock();
  if (execute) {
    const std::string resultName = call.reused ? call.reused->name : target;
    OperatorCall opCall{*this,           command,     call.keywords,    resultName,
                        call.resultType, call.reused, args.callLocation};
    try {
      result = runOperator(op, opCall);
    } catch (const UserError& e) {
      throw withCallingCommand(e, command, args);
    }
  } else if (!call.resultType.empty()) {
    auto c = std::make_shared<Concept>();
    c->name = call.reused ? call.reused->name : target;
    c->type = call.resultType;
    c->definedAt = args.callLocation;
    result = call.reused ? Value(call.reused) : Value(c);
  }
  double cpu = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  if (result.isConcept()) {
    made = result.asConcept();
    if (made->name.empty()) {
      made->name = target;
    }
    concepts_.put(made->name, made);
  }
  // The summary table names the file without its folders, so its columns stay aligned.
  const std::string shortLocation =
      args.callLocation.file ? std::filesystem::path(args.callLocation.file->name()).filename().string() +
                                   ":" + std::to_string(args.callLocation.line)
                             : location;
  timings_.push_back({command, shortLocation, wall});
  message_ << fmt::format("  # End of command #{:04d}   cpu: {:.2f} s   elapsed: {:.2f} s\n", commandCount_,
                          cpu, wall)
           << std::flush;
  return result;
}

// Runs an operator; every exception it lets out becomes a located diagnostic, and the steps of
// a result it had started are written to a MED file.
Value Session::runOperator(Value (*op)(OperatorCall&), OperatorCall& opCall) {
  inProgress_.reset();
  const std::string& command = opCall.command;
  const SourceLocation& at = opCall.location;
  try {
    return op(opCall);
  } catch (const UserError& e) {
    throw keepPartialResult(withUserPaths(e));
  } catch (const InternalError& e) {
    throw keepPartialResult(UserError(msg::make("INTERNAL_1", {{"command", command}}, at)
                                          .withNote(e.what())
                                          .withNote(msg::text("INTERNAL_1.n1"))));
  } catch (const std::exception& e) {
    throw keepPartialResult(
        UserError(diagnosticOf(e, msg::text("DURING.command", {{"command", command}}), at)));
  }
}

// The steps of the result the failed command had started reach the disk: a MED file in the work
// directory, copied back beside the results, named in the diagnostics.
UserError Session::keepPartialResult(const UserError& e) {
  std::shared_ptr<Concept> made = std::move(inProgress_);
  inProgress_.reset();
  auto result = made ? std::dynamic_pointer_cast<const Result>(made->data) : nullptr;
  if (!result || result->steps.empty() || result->mesh == nullptr || options_.keptResultsDirectory.empty()) {
    return e;
  }
  const std::string name = fmt::format("{}.{}.incomplete.rmed", options_.keptResultsStem, made->name);
  const std::filesystem::path work = options_.workDirectory / name;
  const std::filesystem::path destination = options_.keptResultsDirectory / name;
  std::string written;
  try {
    ResultOutput out;
    out.resultName = made->name;
    out.gaussPoints = rigiGaussPoints;
    std::filesystem::remove(work);
    writeMedResult(work, *result->mesh, result->mesh->name(), result.get(), out, false);
    keptFiles_.push_back({work, destination});
    written = destination.string();
  } catch (const std::exception& failure) {
    std::error_code ec;
    std::filesystem::remove(work, ec);
    const auto* user = dynamic_cast<const UserError*>(&failure);
    std::vector<Diagnostic> ds = e.diagnostics();
    ds.front().withNote(msg::text(
        "NOTE.n2", {{"name", made->name},
                    {"reason", user != nullptr ? user->diagnostics().front().message : failure.what()}}));
    return UserError(std::move(ds));
  }
  const ResultStep& last = result->steps.back();
  std::vector<Diagnostic> ds = e.diagnostics();
  for (auto& d : ds) {
    if (d.severity == Severity::Alarm || d.severity == Severity::Info) {
      continue;
    }
    if (d.kind == FailureKind::Interrupted) {
      d.message += ", written to " + written;
    } else {
      d.withNote(msg::text("NOTE.n1", {{"steps_count", result->steps.size()},
                                       {"name", made->name},
                                       {"time", last.time},
                                       {"number", last.number},
                                       {"written", written}}));
    }
    break;
  }
  noteKeptResult(fmt::format("{}: {} step(s) up to INST {:g} in {}", made->name, result->steps.size(),
                             last.time, written));
  return UserError(std::move(ds));
}

Value Session::conceptAttribute(const std::shared_ptr<Concept>& object, const std::string& name,
                                const SourceLocation& at) {
  if (name == "__call__") {
    if (auto function = std::dynamic_pointer_cast<const RealFunction>(object->data)) {
      return makeNativeFunction(object->name, [function, object](const CallArguments& args) {
        return Value(callRealFunction(*function, object->name, args));
      });
    }
  }
  if (ConceptMethod method = findConceptMethod(object->type, name)) {
    return makeNativeFunction(name,
                              [method, object](const CallArguments& args) { return method(*object, args); });
  }
  const std::vector<std::string> methods = conceptMethodNames(object->type);
  Diagnostic d =
      msg::make("CONCEPT_1", {{"name", object->name}, {"type", object->type}, {"name_2", name}}, at);
  if (const std::string suggestion = suggestionNote(name, methods); !suggestion.empty()) {
    d.withNote(suggestion);
  }
  d.withNote(msg::text("CONCEPT_1.n1", {{"type", object->type}, {"join", fmt::join(methods, ", ")}}));
  throw UserError(std::move(d));
}

} // namespace stella
