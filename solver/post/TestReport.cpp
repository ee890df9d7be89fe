#include "TestReport.hpp"

#include "interpreter/Value.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

std::string pad(const std::string& s, std::size_t width) {
  return s.size() >= width ? s : s + std::string(width - s.size(), ' ');
}

// The error and tolerance columns: two significant digits, like "4.8E-11%".
std::string shortNumber(double x) {
  return x == 0.0 ? "0.0" : fmt::format("{:.2G}", x);
}

struct Comparison {
  bool ok;
  std::string error;
  std::string tolerance;
};

Comparison compare(double reference, double computed, double tolerance, bool absolute, double ordreGrandeur) {
  double diff = std::fabs(reference - computed);
  if (std::isnan(computed)) {
    return {false, "NaN", absolute ? shortNumber(tolerance) : shortNumber(tolerance * 100.0) + "%"};
  }
  if (absolute) {
    double tole = std::fabs(tolerance * ordreGrandeur);
    return {diff <= tole, shortNumber(diff), shortNumber(tole)};
  }
  std::string tole = shortNumber(tolerance * 100.0) + "%";
  if (reference == 0.0) {
    bool ok = diff <= std::fabs(tolerance * ordreGrandeur);
    return {ok, ok ? "0.0%" : "999.999999%", tole};
  }
  double relative = diff / std::fabs(reference);
  return {relative <= tolerance, shortNumber(relative * 100.0) + "%", tole};
}

} // namespace

double reduceByTestType(const std::string& type, const std::vector<double>& values) {
  double r = type == "SOMM_ABS" ? std::fabs(values.front()) : values.front();
  for (std::size_t i = 1; i < values.size(); ++i) {
    const double v = values[i];
    if (type == "MIN") {
      r = std::min(r, v);
    } else if (type == "MAX") {
      r = std::max(r, v);
    } else if (type == "SOMM") {
      r += v;
    } else {
      r += std::fabs(v);
    }
  }
  return r;
}

std::string testNumber(double x) {
  std::string s = Value(x).repr();
  std::replace(s.begin(), s.end(), 'e', 'E');
  return s;
}

std::string testHeader(const std::vector<std::pair<std::string, std::string>>& columns) {
  std::string names = "----";
  std::string values = "    ";
  for (const auto& [name, value] : columns) {
    std::size_t width = std::max<std::size_t>({16, name.size() + 1, value.size() + 1});
    names += " " + pad(name, width);
    values += " " + pad(value, width);
  }
  auto trim = [](std::string s) {
    s.erase(s.find_last_not_of(' ') + 1);
    return s + "\n";
  };
  return trim(names) + trim(values);
}

TestOutcome runValueTest(const ValueTest& test, bool referenceOnly) {
  TestOutcome out;
  std::string computed = testNumber(test.computed);
  std::size_t width = std::max<std::size_t>(16, computed.size());
  if (test.valeCalc) {
    width = std::max(width, testNumber(*test.valeCalc).size());
  }
  if (test.valeRefe) {
    width = std::max(width, testNumber(*test.valeRefe).size());
  }
  auto line = [&](const std::string& status, const std::string& kind, const std::string& ref,
                  const std::string& value, const std::string& error, const std::string& tole) {
    std::string s = pad(status, 4) + " " + pad(kind, 16) + " " + pad(test.legend, 16) + " " +
                    pad(ref, width) + " " + pad(value, width) + " " + pad(error, 16) + " " + tole;
    s.erase(s.find_last_not_of(' ') + 1);
    return s + "\n";
  };
  out.text += line("", "REFERENCE", "VALE_REFE", "VALE_CALC", "ERREUR", "TOLE");
  if (test.valeCalc) {
    Comparison c =
        compare(*test.valeCalc, test.computed, test.toleMachine, test.absolute, test.ordreGrandeur);
    std::string status = referenceOnly ? " -" : (c.ok ? " OK" : "NOOK");
    out.text += line(status, "NON_REGRESSION", testNumber(*test.valeCalc), computed, c.error, c.tolerance);
    if (!referenceOnly) {
      ++(c.ok ? out.ok : out.nook);
    }
  }
  if (test.valeRefe) {
    Comparison c = compare(*test.valeRefe, test.computed, test.precision, test.absolute, test.ordreGrandeur);
    out.text += line(c.ok ? " OK" : "NOOK", test.reference.empty() ? "NON_DEFINI" : test.reference,
                     testNumber(*test.valeRefe), computed, c.error, c.tolerance);
    ++(c.ok ? out.ok : out.nook);
  }
  if (test.ordreGrandeur != 1.0) {
    out.text += "     ORDRE DE GRANDEUR : " + testNumber(test.ordreGrandeur) + "\n";
  }
  return out;
}

void reportTest(TestReportSink& sink, const std::vector<std::pair<std::string, std::string>>& header,
                const ValueTest& test) {
  TestOutcome outcome = runValueTest(test, sink.referenceOnlyTests());
  sink.writeTestLines(testHeader(header) + outcome.text + "\n");
  for (int i = 0; i < outcome.ok; ++i) {
    sink.recordTest(true);
  }
  for (int i = 0; i < outcome.nook; ++i) {
    sink.recordTest(false);
  }
}

} // namespace stella
