#include "StopRequest.hpp"
#include "messages/Messages.hpp"

#include <atomic>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <mutex>
#include <unistd.h>

namespace stella {

namespace {

std::atomic<int> requestedReason{0}; // a StopReason
std::atomic<int> requestedSignal{0};
std::atomic<unsigned> limitSeconds{0};
// Standard error as it was at the start: the MED writers send fd 2 to /dev/null for a while.
int messageFd = STDERR_FILENO;

void say(const char* text, std::size_t size) {
  [[maybe_unused]] const ssize_t n = ::write(messageFd, text, size);
}

void onStopSignal(int signal) {
  if (requestedReason.load() == static_cast<int>(StopReason::Signal)) {
    // The second signal: stop at once, as the user asks.
    constexpr char text[] =
        "\nstella: second signal: stopping at once; the work directory is left as it is\n";
    say(text, sizeof(text) - 1);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  requestedSignal.store(signal);
  requestedReason.store(static_cast<int>(StopReason::Signal));
  constexpr char text[] = "\nstella: stop requested: the run stops at the next safe point (end of a step or "
                          "command) and copies its results back; a second signal stops at once\n";
  say(text, sizeof(text) - 1);
}

void onAlarm(int) {
  if (requestedReason.load() == static_cast<int>(StopReason::None)) {
    requestedReason.store(static_cast<int>(StopReason::TimeLimit));
  }
}

void install(int signal, void (*handler)(int), bool keepIgnored) {
  struct sigaction previous {};
  if (::sigaction(signal, nullptr, &previous) == 0 && keepIgnored && previous.sa_handler == SIG_IGN) {
    return;
  }
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(signal, &action, nullptr);
}

const char* signalName(int signal) {
  switch (signal) {
  case SIGINT:
    return "SIGINT";
  case SIGTERM:
    return "SIGTERM";
  default:
    return "a signal";
  }
}

} // namespace

void installStopHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    const int copy = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 3);
    messageFd = copy >= 0 ? copy : STDERR_FILENO;
    install(SIGINT, onStopSignal, true);
    install(SIGTERM, onStopSignal, false);
    install(SIGALRM, onAlarm, false);
    // The file-size limit (ulimit -f) makes write(2) fail with EFBIG, reported with the file,
    // instead of killing the process.
    std::signal(SIGXFSZ, SIG_IGN);
  });
}

void armTimeLimit(unsigned seconds) {
  limitSeconds.store(seconds);
  ::alarm(seconds);
}

StopReason stopReason() {
  return static_cast<StopReason>(requestedReason.load());
}

int stopSignal() {
  return requestedSignal.load();
}

bool stopRequested() {
  return stopReason() != StopReason::None;
}

std::string stopCause() {
  switch (stopReason()) {
  case StopReason::Signal:
    return fmt::format("signal {} ({})", stopSignal(), signalName(stopSignal()));
  case StopReason::TimeLimit:
    return fmt::format("the time limit of {} s (P time_limit)", limitSeconds.load());
  case StopReason::None:
    break;
  }
  return "nothing";
}

void clearStopRequest() {
  requestedReason.store(0);
  requestedSignal.store(0);
}

Diagnostic stopDiagnostic(const std::string& where, SourceLocation at) {
  Diagnostic d = msg::make("STOP_1", {{"stop_cause", stopCause()}, {"where", where}}, std::move(at));
  d.severity = Severity::Exception; // <S>, as code_aster's stops on the time limit
  d.kind = FailureKind::Interrupted;
  d.withNote(stopReason() == StopReason::TimeLimit ? msg::text("STOP_1.n1") : msg::text("STOP_1.n2"));
  return d;
}

} // namespace stella
