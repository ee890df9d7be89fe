#pragma once
// Where TEST_RESU and TEST_TABLE report their lines and count OK/NOOK: the session implements it
// (result and message files, the job's test counts), a unit test can give its own, so the test
// commands need not know the whole Session.

#include <string>

namespace stella {

class TestReportSink {
public:
  virtual ~TestReportSink() = default;
  // --reference-only: NON_REGRESSION lines are printed with '-' and not counted.
  virtual bool referenceOnlyTests() const = 0;
  // The header and comparison lines of one test, for the result file and the message file.
  virtual void writeTestLines(const std::string& text) = 0;
  // One OK (true) or NOOK (false) line.
  virtual void recordTest(bool ok) = 0;
};

} // namespace stella
