// The job diagnostic words and exit codes (code_aster's run_aster/status.py rules).

#include "solver/job/JobDiagnostic.hpp"
#include "solver/session/Session.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

SessionCounts counts(int ok, int nook, int alarms, FailureKind failure = FailureKind::None) {
  SessionCounts c;
  c.testsOk = ok;
  c.testsNook = nook;
  c.alarms = alarms;
  c.failure = failure;
  return c;
}

TEST(JobDiagnostic, Words) {
  EXPECT_STREQ(diagnosticWord(diagnose(counts(3, 0, 0), true)), "OK");
  EXPECT_STREQ(diagnosticWord(diagnose(counts(3, 1, 0), true)), "NOOK_TEST_RESU");
  EXPECT_STREQ(diagnosticWord(diagnose(counts(0, 0, 0), true)), "NO_TEST_RESU");
  EXPECT_STREQ(diagnosticWord(diagnose(counts(0, 0, 0), false)), "OK"); // a study need not test
  EXPECT_STREQ(diagnosticWord(diagnose(counts(1, 0, 2), true)), "<A>_ALARM");
  EXPECT_STREQ(diagnosticWord(diagnose(counts(1, 1, 0, FailureKind::Syntax), true)), "<F>_SYNTAX_ERROR");
  EXPECT_STREQ(diagnosticWord(diagnose(counts(1, 0, 0, FailureKind::Error), true)), "<F>_ERROR");
  EXPECT_STREQ(diagnosticWord(diagnose(counts(1, 0, 0, FailureKind::NoConvergence), true)),
               "<S>_NO_CONVERGENCE");
  EXPECT_STREQ(diagnosticWord(diagnose(counts(1, 0, 0, FailureKind::Abort), true)), "<F>_ABNORMAL_ABORT");
}

TEST(JobDiagnostic, NookWinsOverAlarm) {
  EXPECT_EQ(diagnose(counts(1, 1, 5), true), JobDiagnostic::NookTestResu);
}

TEST(JobDiagnostic, ExitCodes) {
  EXPECT_EQ(exitCode(JobDiagnostic::Ok), 0);
  EXPECT_EQ(exitCode(JobDiagnostic::Alarm), 0);
  EXPECT_NE(exitCode(JobDiagnostic::NookTestResu), 0);
  EXPECT_NE(exitCode(JobDiagnostic::NoTestResu), 0);
  EXPECT_NE(exitCode(JobDiagnostic::SyntaxError), 0);
  EXPECT_NE(exitCode(JobDiagnostic::NoConvergence), 0);
}

TEST(JobDiagnostic, ExpectedDiagnosticBecomesOk) {
  EXPECT_EQ(applyExpected(JobDiagnostic::NoConvergence, {"<S>_NO_CONVERGENCE"}), JobDiagnostic::Ok);
  EXPECT_EQ(applyExpected(JobDiagnostic::Error, {"<S>_NO_CONVERGENCE"}), JobDiagnostic::Error);
}

TEST(JobDiagnostic, FrameHasCodeAsterWords) {
  EXPECT_EQ(diagnosticFrame(JobDiagnostic::Ok),
            std::string(60, '-') + "\n--- DIAGNOSTIC JOB : OK\n" + std::string(60, '-') + "\n");
}

} // namespace
} // namespace stella
