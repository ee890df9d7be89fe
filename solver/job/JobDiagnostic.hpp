#pragma once
// The job diagnostic printed at the end of the message file, with code_aster's words
// (reference §4.2), and the exit code of `stella run`.

#include "interpreter/Diagnostics.hpp"

#include <string>
#include <vector>

namespace stella {

struct SessionCounts;

enum class JobDiagnostic {
  Ok,
  Alarm,         // <A>_ALARM
  NookTestResu,  // NOOK_TEST_RESU
  NoTestResu,    // NO_TEST_RESU
  SyntaxError,   // <F>_SYNTAX_ERROR
  Error,         // <F>_ERROR
  NoConvergence, // <S>_NO_CONVERGENCE
  AbnormalAbort, // <F>_ABNORMAL_ABORT
  Interrupted,   // <S>_INTERRUPTED (a signal)
  TimeLimit      // <S>_CPU_LIMIT (P time_limit)
};

// `isTestcase`: the export has a `P testlist` line (a test case must print OK/NOOK lines).
JobDiagnostic diagnose(const SessionCounts& counts, bool isTestcase);
// `P expected_diag ...` turns a matching diagnostic into OK.
JobDiagnostic applyExpected(JobDiagnostic d, const std::vector<std::string>& expected);

const char* diagnosticWord(JobDiagnostic d);
// 0 for OK and <A>_ALARM; otherwise non-zero, one code per diagnostic (see README).
int exitCode(JobDiagnostic d);
// The closing frame of the message file.
std::string diagnosticFrame(JobDiagnostic d);

} // namespace stella
