// MumpsControls: the memory available to GESTION_MEMOIRE='AUTO' and the summary's numbers.

#include "solver/linalg/MumpsControlsApply.hpp"

#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <sys/resource.h>
#include <unistd.h>

namespace stella::linalg {

namespace {

double memAvailableMegabytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kilobytes = 0.0;
  std::string unit;
  while (in >> key >> kilobytes >> unit) {
    if (key == "MemAvailable:") {
      return kilobytes / 1024.0;
    }
  }
  return std::numeric_limits<double>::infinity();
}

double addressSpaceMegabytes() {
  std::ifstream in("/proc/self/statm");
  double pages = 0.0;
  in >> pages;
  return pages * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

} // namespace

double availableMegabytes() {
  double available = memAvailableMegabytes();
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    const double left = static_cast<double>(limit.rlim_cur) / (1024.0 * 1024.0) - addressSpaceMegabytes();
    available = std::min(available, left);
  }
  return available;
}

std::string fmtReal(double v) {
  return fmt::format("{:.3g}", v);
}

} // namespace stella::linalg
