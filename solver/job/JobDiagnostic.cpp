#include "JobDiagnostic.hpp"

#include "solver/session/Session.hpp"
#include "solver/session/StopRequest.hpp"

#include <algorithm>

namespace stella {

JobDiagnostic diagnose(const SessionCounts& counts, bool isTestcase) {
  switch (counts.failure) {
  case FailureKind::Syntax:
    return JobDiagnostic::SyntaxError;
  case FailureKind::Error:
    return JobDiagnostic::Error;
  case FailureKind::NoConvergence:
    return JobDiagnostic::NoConvergence;
  case FailureKind::Abort:
    return JobDiagnostic::AbnormalAbort;
  case FailureKind::Interrupted:
    return stopReason() == StopReason::TimeLimit ? JobDiagnostic::TimeLimit : JobDiagnostic::Interrupted;
  case FailureKind::None:
    break;
  }
  if (counts.testsNook > 0) {
    return JobDiagnostic::NookTestResu;
  }
  if (isTestcase && counts.testsOk == 0) {
    return JobDiagnostic::NoTestResu;
  }
  if (counts.alarms > 0) {
    return JobDiagnostic::Alarm;
  }
  return JobDiagnostic::Ok;
}

JobDiagnostic applyExpected(JobDiagnostic d, const std::vector<std::string>& expected) {
  if (d == JobDiagnostic::Ok) {
    return d;
  }
  const std::string word = diagnosticWord(d);
  bool match = std::any_of(expected.begin(), expected.end(), [&](const std::string& e) { return e == word; });
  return match ? JobDiagnostic::Ok : d;
}

const char* diagnosticWord(JobDiagnostic d) {
  switch (d) {
  case JobDiagnostic::Ok:
    return "OK";
  case JobDiagnostic::Alarm:
    return "<A>_ALARM";
  case JobDiagnostic::NookTestResu:
    return "NOOK_TEST_RESU";
  case JobDiagnostic::NoTestResu:
    return "NO_TEST_RESU";
  case JobDiagnostic::SyntaxError:
    return "<F>_SYNTAX_ERROR";
  case JobDiagnostic::Error:
    return "<F>_ERROR";
  case JobDiagnostic::NoConvergence:
    return "<S>_NO_CONVERGENCE";
  case JobDiagnostic::AbnormalAbort:
    return "<F>_ABNORMAL_ABORT";
  case JobDiagnostic::Interrupted:
    return "<S>_INTERRUPTED";
  case JobDiagnostic::TimeLimit:
    return "<S>_CPU_LIMIT";
  }
  return "<F>_ABNORMAL_ABORT";
}

int exitCode(JobDiagnostic d) {
  switch (d) {
  case JobDiagnostic::Ok:
  case JobDiagnostic::Alarm:
    return 0;
  case JobDiagnostic::NookTestResu:
  case JobDiagnostic::NoTestResu:
    return 1;
  case JobDiagnostic::SyntaxError:
    return 2;
  case JobDiagnostic::Error:
    return 3;
  case JobDiagnostic::NoConvergence:
    return 4;
  case JobDiagnostic::AbnormalAbort:
    return 5;
  case JobDiagnostic::Interrupted:
    return 6;
  case JobDiagnostic::TimeLimit:
    return 7;
  }
  return 5;
}

std::string diagnosticFrame(JobDiagnostic d) {
  const std::string rule(60, '-');
  return rule + "\n--- DIAGNOSTIC JOB : " + diagnosticWord(d) + "\n" + rule + "\n";
}

} // namespace stella
