// TEST_RESU / TEST_TABLE lines: layout, errors and tolerances as code_aster prints them.

#include "solver/post/TestReport.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

TEST(TestReport, NumbersPrintLikePython) {
  EXPECT_EQ(testNumber(-25.0), "-25.0");
  EXPECT_EQ(testNumber(1.0e-5), "1E-05");
  EXPECT_EQ(testNumber(-2.0380426e6), "-2038042.6");
  EXPECT_EQ(testNumber(1.0e16), "1E+16");
}

TEST(TestReport, RelativeReferenceWithinTolerance) {
  ValueTest t;
  t.legend = "DEPL";
  t.computed = -25.000000000012;
  t.valeCalc = -25.0;
  t.valeRefe = -25.0;
  t.reference = "ANALYTIQUE";
  TestOutcome out = runValueTest(t, false);
  EXPECT_EQ(out.ok, 2);
  EXPECT_EQ(out.nook, 0);
  EXPECT_NE(
      out.text.find(" OK  NON_REGRESSION   DEPL             -25.0            -25.000000000012 4.8E-11%"),
      std::string::npos)
      << out.text;
  EXPECT_NE(out.text.find("0.1%"), std::string::npos) << out.text;
  EXPECT_NE(out.text.find("0.0001%"), std::string::npos) << out.text;
}

TEST(TestReport, OutsideToleranceIsNook) {
  ValueTest t;
  t.legend = "REAC";
  t.computed = -1.9e6;
  t.valeRefe = -2.0380426e6;
  t.reference = "ANALYTIQUE";
  t.precision = 0.05;
  TestOutcome out = runValueTest(t, false);
  EXPECT_EQ(out.nook, 1); // 6.8 % off, 5 % allowed
  EXPECT_NE(out.text.find("\nNOOK ANALYTIQUE       REAC"), std::string::npos) << out.text;
}

TEST(TestReport, AbsoluteCriterion) {
  ValueTest t;
  t.legend = "JEU";
  t.computed = 4.0e-4;
  t.valeRefe = 0.0;
  t.reference = "ANALYTIQUE";
  t.absolute = true;
  t.precision = 1.0e-3;
  EXPECT_EQ(runValueTest(t, false).ok, 1);
  t.computed = 2.0e-3;
  EXPECT_EQ(runValueTest(t, false).nook, 1);
}

TEST(TestReport, RelativeToZeroReference) {
  ValueTest t;
  t.legend = "DX";
  t.computed = 1.0e-9;
  t.valeCalc = 0.0;
  TestOutcome ok = runValueTest(t, false);
  EXPECT_EQ(ok.ok, 1);
  EXPECT_NE(ok.text.find("0.0%"), std::string::npos);
  t.computed = 0.5;
  TestOutcome nook = runValueTest(t, false);
  EXPECT_EQ(nook.nook, 1);
  EXPECT_NE(nook.text.find("999.999999%"), std::string::npos);
}

TEST(TestReport, ReferenceOnlyDoesNotCountNonRegression) {
  ValueTest t;
  t.legend = "DY";
  t.computed = 1.5;
  t.valeCalc = 1.0; // another code's non-regression value: far off, but only information
  t.valeRefe = 1.5;
  t.reference = "SOURCE_EXTERNE";
  TestOutcome out = runValueTest(t, true);
  EXPECT_EQ(out.ok, 1);
  EXPECT_EQ(out.nook, 0);
  EXPECT_NE(out.text.find(" -   NON_REGRESSION"), std::string::npos) << out.text;
}

TEST(TestReport, HeaderColumns) {
  EXPECT_EQ(testHeader({{"RESULTAT", "RES"}, {"NUME_ORDRE", "1"}}),
            "---- RESULTAT         NUME_ORDRE\n     RES              1\n");
}

// reportTest needs only a TestReportSink (not a Session): the header and lines go out in one
// piece, each counted line is recorded once, and the sink's --reference-only is honoured.
class RecordingSink : public TestReportSink {
public:
  bool referenceOnly = false;
  std::string text;
  int ok = 0;
  int nook = 0;
  bool referenceOnlyTests() const override { return referenceOnly; }
  void writeTestLines(const std::string& t) override { text += t; }
  void recordTest(bool passed) override { ++(passed ? ok : nook); }
};

TEST(TestReport, ReportsThroughItsSink) {
  ValueTest t;
  t.legend = "DY";
  t.computed = 1.5;
  t.valeCalc = 1.0; // NOOK as non-regression (50 % off)
  t.valeRefe = 1.5; // OK against the reference
  t.reference = "ANALYTIQUE";
  RecordingSink sink;
  reportTest(sink, {{"TABLE", "T"}}, t);
  EXPECT_EQ(sink.ok, 1);
  EXPECT_EQ(sink.nook, 1);
  EXPECT_EQ(sink.text.rfind("---- TABLE\n     T\n", 0), 0u) << sink.text;
  EXPECT_EQ(sink.text.back(), '\n');
  RecordingSink referenceOnly;
  referenceOnly.referenceOnly = true;
  reportTest(referenceOnly, {{"TABLE", "T"}}, t);
  EXPECT_EQ(referenceOnly.ok, 1);
  EXPECT_EQ(referenceOnly.nook, 0);
}

} // namespace
} // namespace stella
