#pragma once
// Elapsed time of the phases of a static analysis, for the message file and the performance
// report (doc/bench/fem-performance.md): numbering (DOFs, relations, matrix pattern), assembly
// (element matrices into K, internal and load vectors, behaviour integration), factorisation (bordered
// matrix, symbolic analysis, numerical factorisation), solve (triangular solutions), post (stresses at the
// Gauss points and fields stored), and the peak resident memory of the process.

#include <chrono>
#include <string>

namespace stella {

struct PhaseTimes {
  double numbering = 0.0;
  double assembly = 0.0;
  double factorisation = 0.0;
  double solve = 0.0;
  double post = 0.0;
  // STAT_NON_LINE: the rest of the command's time (residual
  // norms and tests, the driver's bookkeeping); zero and not printed for MECA_STATIQUE.
  double other = 0.0;
  // STAT_NON_LINE with CONTACT: the contact constraint's own time (pairing, active set, forces
  // and tangents, CONT_NOEU), without the solutions it asks of the linear solver (in `solve`).
  double contact = 0.0;
  double total() const { return numbering + assembly + factorisation + solve + post + other + contact; }
};

// Peak resident set size of the process so far, in megabytes (getrusage).
double peakResidentMegabytes();

// "   phases (s): numbering 0.012, assembly 0.350, ..." lines for the message file.
std::string formatPhases(const PhaseTimes& t, int analyses, std::size_t equations = 0);

// Adds the seconds elapsed since its construction to a counter when destroyed.
class PhaseClock {
public:
  explicit PhaseClock(double& counter) : counter_(counter), start_(std::chrono::steady_clock::now()) {}
  ~PhaseClock() {
    counter_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  PhaseClock(const PhaseClock&) = delete;
  PhaseClock& operator=(const PhaseClock&) = delete;

private:
  double& counter_;
  std::chrono::steady_clock::time_point start_;
};

} // namespace stella
