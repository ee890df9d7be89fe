// The progress line: nothing without a terminal or during the first half second; then one line
// redrawn in place and erased before other output.

#include "solver/nonlinear/ProgressLine.hpp"

#include <gtest/gtest.h>
#include <sstream>
#include <thread>

namespace stella {
namespace {

TEST(ProgressLine, SilentWithoutTerminal) {
  setProgressTerminal(nullptr);
  ProgressLine line(0.0, 1.0);
  line.show(0.5, 3, 0); // nowhere to draw: no effect, no crash
  EXPECT_EQ(progressTerminal(), nullptr);
}

TEST(ProgressLine, DrawsAfterHalfASecondAndErasesItself) {
  std::ostringstream terminal;
  setProgressTerminal(&terminal);
  {
    ProgressLine line(0.0, 2.0);
    line.show(0.1, 1, 0);
    EXPECT_EQ(terminal.str(), ""); // a short run shows nothing
    std::this_thread::sleep_for(std::chrono::milliseconds(550));
    line.show(0.5, 4, 1);
    EXPECT_EQ(terminal.str().rfind("\r   STAT_NON_LINE  INST 0.5 / 2 (25 %), 4 step(s), 1 cut(s), ", 0), 0u)
        << terminal.str();
    EXPECT_EQ(terminal.str().find('\n'), std::string::npos); // redrawn in place
    line.erase();
    EXPECT_EQ(terminal.str().substr(terminal.str().size() - 4), "\r\x1b[K");
    line.show(1.0, 5, 1);
  } // the destructor erases the last drawing
  EXPECT_EQ(terminal.str().substr(terminal.str().size() - 4), "\r\x1b[K");
  setProgressTerminal(nullptr);
}

} // namespace
} // namespace stella
