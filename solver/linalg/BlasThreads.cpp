// BLAS thread count through OpenBLAS's run-time interface, looked up with dlsym.

#include "solver/linalg/BlasThreads.hpp"

#include <dlfcn.h>

#include <charconv>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

namespace stella::linalg {
namespace {

template <class F> F lookup(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_DEFAULT, name)); // NOLINT: C interface
}

} // namespace

int setBlasThreads(int n) {
  if (auto set = lookup<void (*)(int)>("openblas_set_num_threads"); set != nullptr && n >= 1) {
    set(n);
  }
  return blasThreads();
}

int blasThreads() {
  auto get = lookup<int (*)()>("openblas_get_num_threads");
  return get != nullptr ? get() : 1;
}

std::string blasDescription() {
  auto config = lookup<char* (*)()>("openblas_get_config");
  return config != nullptr ? std::string(config()) : std::string();
}

std::optional<int> blasThreadsFromEnvironment() {
  const char* text = std::getenv("STELLA_BLAS_THREADS");
  if (text == nullptr) {
    return std::nullopt;
  }
  const std::string_view s(text);
  int n = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), n);
  if (error != std::errc() || end != s.data() + s.size() || n < 1 || n > 1024) {
    throw std::invalid_argument("STELLA_BLAS_THREADS='" + std::string(s) +
                                "' is not a whole number of threads from 1 to 1024");
  }
  return n;
}

int blasThreadsFor(int exportCpus) {
  return blasThreadsFromEnvironment().value_or(exportCpus >= 1 ? exportCpus : 1);
}

std::string applyBlasThreads(int exportCpus) {
  const int cpus = exportCpus >= 1 ? exportCpus : 1;
  std::string source = "P ncpus";
  int wanted = cpus;
  try {
    if (auto n = blasThreadsFromEnvironment()) {
      wanted = *n;
      source = "STELLA_BLAS_THREADS";
    }
  } catch (const std::invalid_argument& e) {
    source = std::string(e.what()) + ": P ncpus used instead";
  }
  const int effective = setBlasThreads(wanted);
  if (wanted == 1 && source == "P ncpus") {
    return {};
  }
  std::string line = "  BLAS threads of the factorisations: " + std::to_string(effective) + " (" + source;
  if (effective != wanted) {
    line += "; " + std::to_string(wanted) + " asked, the BLAS (" +
            (blasDescription().empty() ? std::string("not OpenBLAS") : blasDescription()) + ") gives " +
            std::to_string(effective);
  }
  return line + ")\n";
}

} // namespace stella::linalg
