// Parsing of the message file for `stella sweep` (formats: StatNonLine.cpp, PhaseTimes.cpp,
// ContactConstraint::reportStep, and the TEST_RESU lines of reference §4.3).

#include "MessReport.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

namespace stella::sweep {

namespace {

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(' ');
  if (a == std::string::npos) {
    return {};
  }
  return s.substr(a, s.find_last_not_of(' ') - a + 1);
}

// The integer just before `word` in `line` ("converged in 3 iteration(s)": before " iteration").
int integerBefore(const std::string& line, const std::string& word) {
  const auto at = line.find(word);
  if (at == std::string::npos || at == 0) {
    return 0;
  }
  auto start = line.find_last_of(' ', at - 1);
  return std::atoi(line.c_str() + (start == std::string::npos ? 0 : start + 1));
}

double numberAfter(const std::string& line, const std::string& word) {
  const auto at = line.find(word);
  return at == std::string::npos ? 0.0 : std::strtod(line.c_str() + at + word.size(), nullptr);
}

void addPhases(PhaseSums& p, const std::string& line) {
  p.numbering += numberAfter(line, "numbering ");
  p.assembly += numberAfter(line, "assembly ");
  p.factorisation += numberAfter(line, "factorisation ");
  p.solve += numberAfter(line, "solve ");
  p.post += numberAfter(line, "post ");
  p.other += numberAfter(line, "other ");
  p.total += numberAfter(line, "total ");
}

bool parseNumber(const std::string& text, double& value) {
  const std::string t = trimmed(text);
  if (t.empty()) {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

// The column header of a test ("     REFERENCE   LEGENDE   VALE_REFE   VALE_CALC   ERREUR  TOLE").
struct TestColumns {
  std::size_t reference = 0;
  std::size_t computed = 0;
  std::size_t error = 0;
  bool valid() const { return error > computed && computed > reference && reference > 21; }
};

TestColumns columnsOf(const std::string& header) {
  TestColumns c;
  c.reference = header.find("VALE_REFE", 21);
  c.computed = header.find("VALE_CALC", c.reference == std::string::npos ? 0 : c.reference);
  c.error = header.find("ERREUR", c.computed == std::string::npos ? 0 : c.computed);
  if (c.reference == std::string::npos || c.computed == std::string::npos || c.error == std::string::npos) {
    return TestColumns{};
  }
  return c;
}

// A line " OK  ANALYTIQUE       u_r(a)   9.53E-4   9.53E-4   0.01%   1%" under `columns`.
bool parseTestLine(const std::string& line, const TestColumns& columns, const std::string& context,
                   ReferenceTest& test) {
  if (line.size() <= columns.error) {
    return false;
  }
  const std::string verdict = trimmed(line.substr(0, 4));
  if (verdict != "OK" && verdict != "NOOK" && verdict != "-") {
    return false;
  }
  const std::string kind = trimmed(line.substr(5, 16));
  if (kind.empty() || kind == "NON_REGRESSION") {
    return false;
  }
  if (!parseNumber(line.substr(columns.reference, columns.computed - columns.reference), test.reference) ||
      !parseNumber(line.substr(columns.computed, columns.error - columns.computed), test.computed)) {
    return false; // SKIP lines, complex values
  }
  const std::string legend = trimmed(line.substr(21, columns.reference - 21));
  test.name = legend.empty() || legend == "XXXX" ? context : legend;
  test.error = relativeError(test.computed, test.reference);
  return true;
}

} // namespace

double relativeError(double computed, double reference) {
  const double difference = std::abs(computed - reference);
  return reference == 0.0 ? difference : difference / std::abs(reference);
}

MessReport parseMessage(const std::string& text) {
  MessReport r;
  std::istringstream in(text);
  std::string line;
  std::string context; // the values line under "---- RESULTAT ..." / "---- TABLE ..."
  bool contextNext = false;
  TestColumns columns;
  std::map<std::string, int> seen;
  while (std::getline(in, line)) {
    if (contextNext) {
      std::istringstream words(line);
      std::string w;
      context.clear();
      while (words >> w) {
        context += (context.empty() ? "" : " ") + w;
      }
      contextNext = false;
      continue;
    }
    if (line.empty()) {
      columns = TestColumns{};
    } else if (startsWith(line, "---- ")) {
      contextNext = true;
      columns = TestColumns{};
    } else if (startsWith(line, "     REFERENCE ")) {
      columns = columnsOf(line);
    } else if (columns.valid() && line.size() > 5) {
      ReferenceTest test;
      if (parseTestLine(line, columns, context, test)) {
        const int n = ++seen[test.name];
        if (n > 1) {
          test.name += " #" + std::to_string(n);
        }
        r.tests.push_back(test);
      }
    }
    if (line.find("   step ") == 0 && line.find(": converged in ") != std::string::npos) {
      ++r.steps;
      r.newtonIterations += integerBefore(line, " iteration(s), RESI_GLOB_RELA");
    } else if (startsWith(line, "   contact: ") &&
               line.find(" geometric iteration(s)") != std::string::npos) {
      r.geometricIterations += integerBefore(line, " geometric iteration(s)");
      r.contactIterations += integerBefore(line, " contact iteration(s)");
    } else if (startsWith(line, "   phases (s): ")) {
      addPhases(r.phases, line);
    } else if (startsWith(line, "--- DIAGNOSTIC JOB : ")) {
      r.diagnostic = trimmed(line.substr(21));
    }
  }
  return r;
}

} // namespace stella::sweep
