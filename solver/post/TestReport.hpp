#pragma once
// The OK/NOOK lines of TEST_RESU and TEST_TABLE, in code_aster's layout (reference §4.3):
// a header pair naming what is tested, then one line per compared value:
//   " OK  NON_REGRESSION   DEPL             -25.0            -25.000000000012 4.8E-11%         0.0001%"
// A NON_REGRESSION line compares with VALE_CALC (tolerance TOLE_MACHINE); a reference line
// (ANALYTIQUE, SOURCE_EXTERNE, AUTRE_ASTER, NON_DEFINI) with VALE_REFE (tolerance PRECISION).

#include "TestReportSink.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace stella {

struct ValueTest {
  std::string legend; // LEGENDE, or the field / parameter name
  double computed = 0.0;
  std::optional<double> valeCalc;
  double toleMachine = 1.0e-6;
  std::optional<double> valeRefe;
  std::string reference; // ANALYTIQUE, ...; empty when no reference line
  double precision = 1.0e-3;
  bool absolute = false;      // CRITERE='ABSOLU'
  double ordreGrandeur = 1.0; // ORDRE_GRANDEUR
};

struct TestOutcome {
  std::string text; // the lines, each ending with '\n'
  int ok = 0;
  int nook = 0;
};

// The header pair: first line "---- " + names, second the values, 16-character columns.
std::string testHeader(const std::vector<std::pair<std::string, std::string>>& columns);

// The comparison lines. With `referenceOnly`, NON_REGRESSION lines are printed with "-" as
// status and not counted.
TestOutcome runValueTest(const ValueTest& test, bool referenceOnly);

// TYPE_TEST of TEST_RESU and TEST_TABLE: MIN, MAX, SOMM or SOMM_ABS of `values` (not empty).
double reduceByTestType(const std::string& type, const std::vector<double>& values);

// Writes the header and the lines of `test` to `sink` and counts its OK/NOOK lines there.
void reportTest(TestReportSink& sink, const std::vector<std::pair<std::string, std::string>>& header,
                const ValueTest& test);

// Python's %s of a real with 'e' printed as 'E' (how code_aster prints tested values).
std::string testNumber(double x);

} // namespace stella
