#pragma once
// What `stella sweep` reads in a run's message file: the job diagnostic, the iterations and phase
// times STAT_NON_LINE printed, and the reference lines of TEST_RESU / TEST_TABLE.

#include <string>
#include <vector>

namespace stella::sweep {

struct ReferenceTest {
  std::string name; // the LEGENDE, or the tested field and component when it has none
  double reference = 0.0;
  double computed = 0.0;
  double error = 0.0; // relativeError(computed, reference)
};

struct PhaseSums { // seconds, summed over every STAT_NON_LINE of the run
  double numbering = 0.0;
  double assembly = 0.0;
  double factorisation = 0.0;
  double solve = 0.0;
  double post = 0.0;
  double other = 0.0;
  double total = 0.0;
};

struct MessReport {
  std::string diagnostic; // OK, <A>_ALARM, NOOK_TEST_RESU, <S>_NO_CONVERGENCE...; "" if none printed
  int steps = 0;          // converged steps
  int newtonIterations = 0;
  int contactIterations = 0;
  int geometricIterations = 0;
  PhaseSums phases;
  std::vector<ReferenceTest> tests;
};

// |computed - reference| / |reference|; |computed - reference| when the reference is 0.
double relativeError(double computed, double reference);

MessReport parseMessage(const std::string& text);

// The results file an external series' command writes ({out}, doc/sweep.md): one line per test,
// `COMPUTED REFERENCE NAME` (two numbers, then the test's name, spaces allowed); blank lines and
// lines starting with # are skipped. Throws SweepError naming the line of any other line.
MessReport parseExternalResult(const std::string& text);

} // namespace stella::sweep
