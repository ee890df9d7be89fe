// ScopedMemoryLimit: RLIMIT_AS lowered for the duration of the run, then restored.

#include "solver/session/MemoryLimit.hpp"

#include <atomic>
#include <fstream>
#include <string>
#include <sys/resource.h>

namespace stella {

namespace {
std::atomic<double> limitInForce{0.0};

// The process's address space now (VmSize of /proc/self/status, bytes; 0 when unknown).
unsigned long long addressSpaceBytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmSize:") {
      unsigned long long kib = 0;
      status >> kib;
      return kib * 1024ULL;
    }
    status.ignore(1 << 12, '\n');
  }
  return 0;
}
} // namespace

ScopedMemoryLimit::ScopedMemoryLimit(double mebibytes) {
  if (!(mebibytes > 0.0)) {
    return;
  }
  rlimit current{};
  if (getrlimit(RLIMIT_AS, &current) != 0) {
    return;
  }
  // Counted beyond the program's own footprint (libraries, the BLAS threads' stacks and buffers):
  // what the limit bounds is what the study allocates, whichever BLAS the machine has.
  footprint_ = static_cast<double>(addressSpaceBytes()) / (1024.0 * 1024.0);
  const auto bytes = static_cast<rlim_t>((mebibytes + footprint_) * 1024.0 * 1024.0);
  rlimit lowered = current;
  lowered.rlim_cur = current.rlim_max == RLIM_INFINITY || bytes < current.rlim_max ? bytes : current.rlim_max;
  if (setrlimit(RLIMIT_AS, &lowered) != 0) {
    return;
  }
  previous_ = current.rlim_cur;
  applied_ = true;
  limitInForce = mebibytes;
}

ScopedMemoryLimit::~ScopedMemoryLimit() {
  if (!applied_) {
    return;
  }
  rlimit current{};
  getrlimit(RLIMIT_AS, &current);
  current.rlim_cur = static_cast<rlim_t>(previous_);
  setrlimit(RLIMIT_AS, &current);
  limitInForce = 0.0;
}

double activeMemoryLimit() {
  return limitInForce.load();
}

} // namespace stella
