// ProgressLine: one line redrawn with a carriage return on the terminal.

#include "solver/nonlinear/ProgressLine.hpp"

#include <fmt/format.h>

namespace stella {

namespace {
std::ostream* gTerminal = nullptr;
}

void setProgressTerminal(std::ostream* terminal) {
  gTerminal = terminal;
}

std::ostream* progressTerminal() {
  return gTerminal;
}

ProgressLine::ProgressLine(double startTime, double endTime)
    : out_(gTerminal), start_(startTime), end_(endTime), began_(std::chrono::steady_clock::now()) {}

ProgressLine::~ProgressLine() {
  erase();
}

void ProgressLine::show(double time, int steps, int cuts) {
  if (out_ == nullptr) {
    return;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  if (seconds < 0.5) {
    return;
  }
  const double span = end_ - start_;
  const double percent = span > 0.0 ? 100.0 * (time - start_) / span : 100.0;
  *out_ << fmt::format(
               "\r   STAT_NON_LINE  INST {:g} / {:g} ({:.0f} %), {} step(s), {} cut(s), {:.1f} s\x1b[K", time,
               end_, percent, steps, cuts, seconds)
        << std::flush;
  drawn_ = true;
}

void ProgressLine::erase() {
  if (drawn_ && out_ != nullptr) {
    *out_ << "\r\x1b[K" << std::flush;
    drawn_ = false;
  }
}

} // namespace stella
