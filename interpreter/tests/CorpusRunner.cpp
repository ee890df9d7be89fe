// The table-driven runner of the language corpus (interpreter/corpus/*.comm). Each file states
// its expectations in comments:
//   # expect-error: ID       on the line where the error must be reported (also for syntax errors)
//   # expect-alarm: ID       on the line where the alarm must be reported
//   # expect-output: TEXT    one line printed by print(), in order
//   # expect-call: CMD TARGET  one command call with its assignment target, in order (all calls
//                              are checked when any expect-call line is present)
//   # expect-status: completed|finished|syntax-error|failed
//   # budget: operations=N | memory=MIB   the evaluation budget of the run (default: the
//                                         interpreter's)
// Modes: `FILE...` checks expectations; `--roundtrip PATH...` checks that every .comm under the
// paths (found when the test runs, so files added later are covered) parses, unless it is
// malformed on purpose, and re-parses to the same tree after pretty-printing; `--no-crash PATH...` runs every
// file through lexer, parser and evaluator and only requires that nothing crashes.
#include "FakeHandler.hpp"
#include "interpreter/Formatter.hpp"
#include "interpreter/Interpreter.hpp"
#include "interpreter/Parser.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;
using namespace stella;
using namespace stella::testing;

namespace {

struct Expected {
  int line;
  std::string id;
};

struct Expectations {
  std::vector<Expected> errors;
  std::vector<Expected> alarms;
  std::vector<std::string> output;
  std::vector<std::string> calls;
  std::string status;
  InterpreterOptions options;
};

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r' || s.back() == '\t')) {
    s.pop_back();
  }
  std::size_t b = s.find_first_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b);
}

Expectations readExpectations(const SourceFile& file) {
  Expectations e;
  for (int l = 1; l <= file.lineCount(); ++l) {
    std::string line(file.line(l));
    auto take = [&](const std::string& tag, auto&& f) {
      std::size_t at = line.find("# " + tag + ":");
      if (at != std::string::npos) {
        std::string rest = line.substr(at + tag.size() + 3);
        if (!rest.empty() && rest[0] == ' ') {
          rest.erase(0, 1);
        }
        f(rest);
      }
    };
    auto ids = [&](std::vector<Expected>& into) {
      return [&into, l](const std::string& r) {
        std::istringstream list(r);
        std::string id;
        while (std::getline(list, id, ',')) {
          into.push_back({l, trim(id)});
        }
      };
    };
    take("expect-error", ids(e.errors));
    take("expect-alarm", ids(e.alarms));
    take("expect-output", [&](const std::string& r) {
      std::string text = r;
      while (!text.empty() && text.back() == '\r') {
        text.pop_back();
      }
      e.output.push_back(text);
    });
    take("expect-call", [&](const std::string& r) { e.calls.push_back(trim(r)); });
    take("expect-status", [&](const std::string& r) { e.status = trim(r); });
    take("budget", [&](const std::string& r) {
      const std::string setting = trim(r);
      const std::size_t eq = setting.find('=');
      const long long value = std::stoll(setting.substr(eq + 1));
      if (setting.rfind("operations", 0) == 0) {
        e.options.operationBudget = value;
      } else {
        e.options.memoryBudget = value << 20;
      }
    });
  }
  return e;
}

const char* statusName(RunStatus s) {
  switch (s) {
  case RunStatus::Completed:
    return "completed";
  case RunStatus::Finished:
    return "finished";
  case RunStatus::SyntaxError:
    return "syntax-error";
  case RunStatus::Failed:
    return "failed";
  }
  return "?";
}

bool checkFile(const std::string& path) {
  auto file = SourceFile::load(path);
  Expectations expected = readExpectations(*file);
  RecordingSink sink;
  FakeHandler handler;
  Interpreter interpreter(handler, sink, expected.options);
  for (const auto& name : fakeCommandNames()) {
    interpreter.defineCommand(name);
  }
  RunStatus status = interpreter.run(file);
  std::vector<std::string> problems;

  auto matchAll = [&](Severity severity, const std::vector<Expected>& wanted, const char* what) {
    std::vector<bool> used(wanted.size(), false);
    for (const auto& d : sink.diagnostics) {
      bool relevant = severity == Severity::Fatal
                          ? (d.severity == Severity::Fatal || d.severity == Severity::Exception)
                          : d.severity == severity;
      if (!relevant) {
        continue;
      }
      bool found = false;
      for (std::size_t i = 0; i < wanted.size(); ++i) {
        if (!used[i] && wanted[i].id == d.id && wanted[i].line == d.location.line) {
          used[i] = found = true;
          break;
        }
      }
      if (!found) {
        problems.push_back(std::string("unexpected ") + what + ":\n" + formatDiagnostic(d));
      }
    }
    for (std::size_t i = 0; i < wanted.size(); ++i) {
      if (!used[i]) {
        problems.push_back(std::string("missing ") + what + " " + wanted[i].id + " at line " +
                           std::to_string(wanted[i].line));
      }
    }
  };
  matchAll(Severity::Fatal, expected.errors, "error");
  matchAll(Severity::Alarm, expected.alarms, "alarm");

  std::vector<std::string> printed;
  for (const auto& message : sink.printed()) {
    std::istringstream lines(message);
    std::string l;
    bool any = false;
    while (std::getline(lines, l)) {
      printed.push_back(l);
      any = true;
    }
    if (!any) {
      printed.emplace_back();
    }
  }
  if (printed != expected.output) {
    std::string text = "printed output differs; expected:\n";
    for (const auto& l : expected.output) {
      text += "  | " + l + "\n";
    }
    text += "got:\n";
    for (const auto& l : printed) {
      text += "  | " + l + "\n";
    }
    problems.push_back(text);
  }
  if (!expected.calls.empty()) {
    std::vector<std::string> calls;
    for (const auto& c : handler.calls) {
      calls.push_back(trim(c.command + " " + c.target));
    }
    if (calls != expected.calls) {
      std::string text = "command calls differ; got:\n";
      for (const auto& c : calls) {
        text += "  " + c + "\n";
      }
      problems.push_back(text);
    }
  }
  std::string wantedStatus = expected.status;
  if (wantedStatus.empty()) {
    bool syntax = std::any_of(expected.errors.begin(), expected.errors.end(),
                              [](const Expected& e) { return e.id.rfind("SYNTAX_", 0) == 0; });
    wantedStatus = syntax ? "syntax-error" : (!expected.errors.empty() ? "failed" : "finished");
    if (expected.errors.empty() && std::any_of(expected.alarms.begin(), expected.alarms.end(),
                                               [](const Expected& e) { return e.id == "LANG_FIN"; })) {
      wantedStatus = "completed";
    }
  }
  if (wantedStatus != statusName(status)) {
    problems.push_back("status: expected " + wantedStatus + ", got " + statusName(status));
  }
  if (problems.empty()) {
    std::cout << "PASS " << path << "\n";
    return true;
  }
  std::cout << "FAIL " << path << "\n";
  for (const auto& p : problems) {
    std::cout << p << "\n";
  }
  for (const auto& d : sink.diagnostics) {
    if (d.id != "PRINT") {
      std::cout << formatDiagnostic(d);
    }
  }
  return false;
}

std::vector<std::string> commFiles(const std::vector<std::string>& paths, const std::string& extension) {
  std::vector<std::string> out;
  for (const auto& p : paths) {
    if (fs::is_directory(p)) {
      for (auto it = fs::recursive_directory_iterator(p); it != fs::recursive_directory_iterator(); ++it) {
        const auto& entry = *it;
        std::string name = entry.path().filename().string();
        if (entry.is_directory() && (name.rfind("build", 0) == 0 || name.rfind(".", 0) == 0)) {
          it.disable_recursion_pending(); // build trees and hidden folders hold copies
          continue;
        }
        if (entry.is_regular_file() && (extension.empty() || entry.path().extension() == extension)) {
          out.push_back(entry.path().string());
        }
      }
    } else {
      out.push_back(p);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A file that does not parse is accepted only when it is malformed on purpose: a file of the
// fuzzing corpus, a language test that expects a syntax error, or text after FIN() (ignored).
bool malformedOnPurpose(const std::string& path, const SourceFile& file) {
  if (path.find("/fuzz/corpus/") != std::string::npos) {
    return true;
  }
  for (int l = 1; l <= file.lineCount(); ++l) {
    std::string_view line = file.line(l);
    if (line.find("# expect-error: SYNTAX") != std::string_view::npos ||
        line.find("# expect-status: syntax-error") != std::string_view::npos) {
      return true;
    }
  }
  return false;
}

bool roundTrip(const std::string& path, int& checked, int& malformed) {
  auto file = SourceFile::load(path);
  ParseResult first = parseFile(file, true);
  if (!first.errors.empty()) {
    if (malformedOnPurpose(path, *file) || errorsOnlyAfterFin(first)) {
      ++malformed;
      return true; // nothing to print
    }
    std::cout << "FAIL " << path << ": does not parse:\n";
    for (const auto& d : first.errors) {
      std::cout << formatDiagnostic(d);
    }
    return false;
  }
  ++checked;
  std::string printed = formatModule(*first.module, first.comments);
  auto again = SourceFile::fromText(path + " (formatted)", printed);
  ParseResult second = parseFile(again);
  if (!second.errors.empty()) {
    std::cout << "FAIL " << path << ": the formatted text does not parse:\n";
    for (const auto& d : second.errors) {
      std::cout << formatDiagnostic(d);
    }
    std::cout << printed;
    return false;
  }
  std::string a = dumpModule(*first.module, false);
  std::string b = dumpModule(*second.module, false);
  if (a != b) {
    std::cout << "FAIL " << path << ": the formatted text parses to another tree\n--- formatted:\n"
              << printed;
    return false;
  }
  // printing is idempotent
  if (formatModule(*second.module, {}) != formatModule(*first.module, {})) {
    std::cout << "FAIL " << path << ": formatting twice changes the text\n";
    return false;
  }
  return true;
}

bool noCrash(const std::string& path) {
  auto file = SourceFile::load(path);
  RecordingSink sink;
  FakeHandler handler(false);
  InterpreterOptions options;
  options.whileIterationCap = 1000;
  options.operationBudget = 200000;
  options.maxSequenceLength = 100000;
  options.maxStringLength = 1000000;
  Interpreter interpreter(handler, sink, options);
  for (const auto& name : fakeCommandNames()) {
    interpreter.defineCommand(name);
  }
  (void)dumpTokens(file);
  ParseResult parsed = parseFile(file, true);
  if (parsed.errors.empty()) {
    (void)formatModule(*parsed.module, parsed.comments);
  }
  interpreter.run(file);
  for (const auto& d : sink.diagnostics) {
    (void)formatDiagnostic(d);
  }
  return true;
}

} // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    std::cerr << "usage: stella_language_runner FILE.comm... | --roundtrip PATH... | --no-crash PATH...\n";
    return 2;
  }
  int failures = 0;
  int passed = 0;
  try {
    if (args[0] == "--roundtrip") {
      int checked = 0;
      int malformed = 0;
      for (const auto& f : commFiles({args.begin() + 1, args.end()}, ".comm")) {
        roundTrip(f, checked, malformed) ? ++passed : ++failures;
      }
      std::cout << checked << " files printed and re-parsed, " << malformed
                << " malformed on purpose (fuzzing corpus, syntax-error tests)\n";
    } else if (args[0] == "--no-crash") {
      for (const auto& f : commFiles({args.begin() + 1, args.end()}, "")) {
        noCrash(f) ? ++passed : ++failures;
      }
    } else {
      for (const auto& f : commFiles(args, ".comm")) {
        checkFile(f) ? ++passed : ++failures;
      }
    }
  } catch (const UserError& e) {
    std::cout << formatDiagnostic(e.first());
    return 1;
  }
  std::cout << passed << " passed, " << failures << " failed\n";
  return failures == 0 ? 0 : 1;
}
