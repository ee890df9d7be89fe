// The evaluation budget (WorkMeter.hpp): operations counted by the evaluator, memory measured as
// the process's resident size from /proc/self/statm.
#include "WorkMeter.hpp"

#include "Runtime.hpp"

#include <algorithm>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>

namespace stella {

namespace {

thread_local WorkMeter* active = nullptr;

std::int64_t defaultMemoryLimit() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGESIZE);
  std::int64_t limit = EvaluationBudget::defaultMemoryBytes;
  if (pages > 0 && pageSize > 0) {
    limit = std::min(limit, static_cast<std::int64_t>(pages) * pageSize / 2);
  }
  return limit;
}

std::string withThousands(std::int64_t n) {
  std::string digits = std::to_string(n);
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) {
      out += ' ';
    }
    out += digits[i];
  }
  return out;
}

} // namespace

WorkMeter* activeWorkMeter() {
  return active;
}

void setActiveWorkMeter(WorkMeter* meter) {
  active = meter;
}

std::int64_t residentBytes() {
  static const int fd = open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    return 0;
  }
  char buffer[128] = {};
  const ssize_t n = pread(fd, buffer, sizeof(buffer) - 1, 0);
  if (n <= 0) {
    return 0;
  }
  long long size = 0;
  long long resident = 0;
  if (std::sscanf(buffer, "%lld %lld", &size, &resident) != 2) {
    return 0;
  }
  return static_cast<std::int64_t>(resident) * sysconf(_SC_PAGESIZE);
}

std::string formatBytes(std::int64_t bytes) {
  constexpr std::int64_t mib = std::int64_t{1} << 20;
  if (bytes >= (std::int64_t{1} << 30) && bytes % (std::int64_t{1} << 30) == 0) {
    return std::to_string(bytes >> 30) + " GiB";
  }
  return std::to_string((bytes + mib / 2) / mib) + " MiB";
}

WorkMeter::WorkMeter(const EvaluationBudget& budget)
    : operationLimit_(budget.operations > 0 ? budget.operations : INT64_MAX),
      memoryLimit_(budget.memoryBytes > 0 ? budget.memoryBytes : defaultMemoryLimit()),
      baseline_(residentBytes()) {}

void WorkMeter::enterCommand() {
  if (commandDepth_++ == 0) {
    commandStart_ = residentBytes();
  }
}

void WorkMeter::leaveCommand() {
  if (--commandDepth_ == 0) {
    baseline_ += residentBytes() - commandStart_;
    pending_ = 0;
  }
}

std::int64_t WorkMeter::languageMemory() const {
  return residentBytes() - baseline_;
}

void WorkMeter::operationsExceeded() const {
  langError("LANG_BUDGET", {{"with_thousands", withThousands(operationLimit_)}});
}

void WorkMeter::checkMemory(std::int64_t upcoming) {
  pending_ = 0;
  if (commandDepth_ > 0) {
    return; // a command's memory is the solver's
  }
  const std::int64_t used = languageMemory() + upcoming;
  if (used > memoryLimit_) {
    langError("LANG_BUDGET.2",
              {{"format_bytes", formatBytes(used)}, {"format_bytes_2", formatBytes(memoryLimit_)}});
  }
}

} // namespace stella
