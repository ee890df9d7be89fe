#pragma once
// A child process of `stella sweep`: started with its output in a log file, measured by wait4
// (wall time, CPU time of the child, its peak resident memory), stopped after a timeout.

#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace stella::sweep {

struct ChildOutcome {
  int exitCode = -1; // -1 when killed by a signal
  int signal = 0;
  bool timedOut = false;
  double wallSeconds = 0.0;
  double cpuSeconds = 0.0; // user + system of the child
  double peakMemoryMiB = 0.0;
};

class Child {
public:
  // Starts argv[0] with `argv` in `directory`, stdout and stderr to `log`; throws SweepError when
  // the process cannot be started.
  Child(const std::vector<std::string>& argv, const std::filesystem::path& directory,
        const std::filesystem::path& log, double timeoutSeconds);
  // True once the child has ended (then outcome() holds what it did); kills it past the timeout.
  bool poll();
  const ChildOutcome& outcome() const { return outcome_; }

private:
  pid_t pid_ = -1;
  double started_ = 0.0;
  double timeout_ = 0.0;
  double terminatedAt_ = 0.0;
  ChildOutcome outcome_;
};

// Runs a child to its end (polling every few milliseconds).
ChildOutcome runChild(const std::vector<std::string>& argv, const std::filesystem::path& directory,
                      const std::filesystem::path& log, double timeoutSeconds);

double monotonicSeconds();

} // namespace stella::sweep
