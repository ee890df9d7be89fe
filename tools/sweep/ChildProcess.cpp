// Child processes of `stella sweep`: posix_spawn, wait4 with WNOHANG, SIGTERM past the timeout
// (stella stops at a safe point), SIGKILL 10 s later.

#include "ChildProcess.hpp"
#include "SweepSpec.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace stella::sweep {

double monotonicSeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

Child::Child(const std::vector<std::string>& argv, const std::filesystem::path& directory,
             const std::filesystem::path& log, double timeoutSeconds)
    : timeout_(timeoutSeconds) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  std::vector<char*> args;
  for (const auto& a : argv) {
    args.push_back(const_cast<char*>(a.c_str()));
  }
  args.push_back(nullptr);
  std::string cwd = directory.string();
  std::vector<std::string> shell;
  if (!directory.empty()) {
    // The child starts in `directory`: through the shell, with the arguments as positional ones.
    shell = {"/bin/sh", "-c", "cd \"$0\" && exec \"$@\"", cwd};
    shell.insert(shell.end(), argv.begin(), argv.end());
    args.clear();
    for (const auto& a : shell) {
      args.push_back(const_cast<char*>(a.c_str()));
    }
    args.push_back(nullptr);
  }
  started_ = monotonicSeconds();
  const int rc = posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    throw SweepError("cannot start " + argv[0] + ": " + std::strerror(rc));
  }
}

bool Child::poll() {
  int status = 0;
  rusage usage{};
  const pid_t done = wait4(pid_, &status, WNOHANG, &usage);
  const double now = monotonicSeconds();
  if (done == 0) {
    if (timeout_ > 0.0 && now - started_ > timeout_ && terminatedAt_ == 0.0) {
      outcome_.timedOut = true;
      terminatedAt_ = now;
      kill(pid_, SIGTERM);
    } else if (terminatedAt_ > 0.0 && now - terminatedAt_ > 10.0) {
      kill(pid_, SIGKILL);
    }
    return false;
  }
  if (done < 0 && errno == EINTR) {
    return false;
  }
  outcome_.wallSeconds = now - started_;
  outcome_.cpuSeconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                        1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  outcome_.peakMemoryMiB = static_cast<double>(usage.ru_maxrss) / 1024.0; // kilobytes on Linux
  if (done > 0 && WIFEXITED(status)) {
    outcome_.exitCode = WEXITSTATUS(status);
  } else if (done > 0 && WIFSIGNALED(status)) {
    outcome_.signal = WTERMSIG(status);
  }
  return true;
}

ChildOutcome runChild(const std::vector<std::string>& argv, const std::filesystem::path& directory,
                      const std::filesystem::path& log, double timeoutSeconds) {
  Child child(argv, directory, log, timeoutSeconds);
  while (!child.poll()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return child.outcome();
}

} // namespace stella::sweep
