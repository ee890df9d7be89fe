#pragma once
// The live progress line of a long STAT_NON_LINE on a terminal: "INST 0.42 / 1 (42 %), 17 steps,
// 2 cuts, 12.3 s" redrawn in place after each step. It goes to the terminal only (never to the
// message file): the command-line tool enables it when standard output is a terminal; it shows
// after the run has lasted half a second and erases itself before anything else is written.

#include <chrono>
#include <ostream>

namespace stella {

// The stream the progress line is drawn on (null: no progress line, the default).
void setProgressTerminal(std::ostream* terminal);
std::ostream* progressTerminal();

class ProgressLine {
public:
  ProgressLine(double startTime, double endTime);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // Redraws the line after a converged step.
  void show(double time, int steps, int cuts);
  // Erases it (before the message stream writes again).
  void erase();

private:
  std::ostream* out_;
  double start_;
  double end_;
  std::chrono::steady_clock::time_point began_;
  bool drawn_ = false;
};

} // namespace stella
