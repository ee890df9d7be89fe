// runSupervised: the study in a child process, its JobResult sent back through a pipe; a child
// that dies on a signal is rescued by the parent (rescueCrashedRun). The child runs in its own
// process group, so a terminal's Ctrl-C reaches it once, forwarded by the parent, and the
// "second signal stops at once" rule of StopRequest keeps its meaning.

#include "JobSpec.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace stella {

namespace {

volatile sig_atomic_t childPid = 0;
volatile sig_atomic_t lastForwarded = 0;

void forwardSignal(int signal) {
  if (childPid > 0) {
    lastForwarded = signal;
    kill(childPid, signal);
  }
}

constexpr int forwarded[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGXCPU};

// The parent forwards the stop signals while the child runs, and restores its handlers after. A
// signal the run was started with ignored stays ignored (nohup, a background job without job
// control), as StopRequest honours it.
class SignalForwarding {
public:
  SignalForwarding() {
    struct sigaction action {};
    action.sa_handler = forwardSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (std::size_t i = 0; i < std::size(forwarded); ++i) {
      sigaction(forwarded[i], nullptr, &previous_[i]);
      if (previous_[i].sa_handler != SIG_IGN) {
        sigaction(forwarded[i], &action, nullptr);
      }
    }
  }
  ~SignalForwarding() {
    restore();
    childPid = 0;
    lastForwarded = 0;
  }
  // The dispositions the process started with (the child runs with them).
  void restore() {
    for (std::size_t i = 0; i < std::size(forwarded); ++i) {
      sigaction(forwarded[i], &previous_[i], nullptr);
    }
  }
  SignalForwarding(const SignalForwarding&) = delete;
  SignalForwarding& operator=(const SignalForwarding&) = delete;

private:
  struct sigaction previous_[std::size(forwarded)]{};
};

// One record per line: D <diagnostic>, W <written file>, F <copy failure>, K <kept work directory>.
std::string serialise(const JobResult& job) {
  std::ostringstream out;
  out << "D " << static_cast<int>(job.diagnostic) << "\n";
  for (const auto& f : job.resultFiles) {
    out << "W " << f.string() << "\n";
  }
  for (const auto& f : job.copyFailures) {
    out << "F " << f << "\n";
  }
  if (!job.workDirectory.empty()) {
    out << "K " << job.workDirectory.string() << "\n";
  }
  return out.str();
}

JobResult deserialise(const std::string& text) {
  JobResult job;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2) {
      continue;
    }
    const std::string value = line.substr(2);
    switch (line[0]) {
    case 'D':
      job.diagnostic = static_cast<JobDiagnostic>(std::stoi(value));
      break;
    case 'W':
      job.resultFiles.emplace_back(value);
      break;
    case 'F':
      job.copyFailures.push_back(value);
      break;
    case 'K':
      job.workDirectory = value;
      break;
    default:
      break;
    }
  }
  return job;
}

void writeAll(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      return;
    }
    done += static_cast<std::size_t>(n);
  }
}

std::string readAll(int fd) {
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) {
      continue;
    }
    if (n <= 0) {
      return text;
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
}

[[noreturn]] void runChild(const JobSpec& spec, const RunOptions& options, const std::filesystem::path& work,
                           int fd, SignalForwarding& forwarding) {
  setpgid(0, 0);
  forwarding.restore();
  // A parent killed outright (kill -9) cannot forward: the run then stops as on SIGTERM.
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  std::string record;
  try {
    RunOptions inChild = options;
    inChild.supervised = false;
    record = serialise(runInWork(spec, inChild, work));
  } catch (...) {
    record = "D " + std::to_string(static_cast<int>(JobDiagnostic::AbnormalAbort)) + "\n";
  }
  writeAll(fd, record);
  close(fd);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  // No MPI_Finalize: a world of one without a daemon ends with the process, and MPI_Finalize
  // runs the parallel HDF5's termination (MED), which crashed after a failed MED write
  // (faults.full-disk).
  _exit(0);
}

} // namespace

JobResult runSupervised(const JobSpec& spec, const RunOptions& options, const std::filesystem::path& work) {
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  int fds[2];
  if (pipe(fds) != 0) {
    return runInWork(spec, options, work); // no pipe: run in this process, unsupervised
  }
  SignalForwarding forwarding;
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return runInWork(spec, options, work);
  }
  if (pid == 0) {
    close(fds[0]);
    runChild(spec, options, work, fds[1], forwarding);
  }
  childPid = pid;
  setpgid(pid, pid); // also here: no race with a signal arriving before the child did it
  close(fds[1]);
  const std::string record = readAll(fds[0]);
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    if (signal == lastForwarded) {
      // The user's second stop signal ended the run at once: so does this process.
      std::signal(signal, SIG_DFL);
      std::raise(signal);
    }
    return rescueCrashedRun(spec, options, work, signal);
  }
  return deserialise(record);
}

} // namespace stella
