// The numeric P lines of an export: one parser, a rule per parameter.

#include "ExportParameters.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <optional>

namespace stella {

namespace {

struct NumberRule {
  const char* name;
  const char* id;
  const char* expects; // "one positive number of seconds"
  const char* example; // "3600"
  bool whole;          // digits only (strtol), else any real (strtod)
  bool (*inRange)(double);
};

// The value of `P <rule.name> <number>`, nothing when the line is absent.
std::optional<double> numberParameter(const Export& study, const NumberRule& rule) {
  if (!study.hasParameter(rule.name)) {
    return std::nullopt;
  }
  const std::vector<std::string> words = study.parameter(rule.name);
  char* end = nullptr;
  double value = -1.0;
  if (words.size() == 1) {
    const char* text = words.front().c_str();
    value = rule.whole ? static_cast<double>(std::strtol(text, &end, 10)) : std::strtod(text, &end);
  }
  if (words.size() != 1 || end == words.front().c_str() || *end != '\0' || !rule.inRange(value)) {
    throw UserError(msg::make(rule.id, {{"name", rule.name},
                                        {"expects", rule.expects},
                                        {"words", fmt::join(words, " ")},
                                        {"file", study.file.string()},
                                        {"example", rule.example}}));
  }
  return value;
}

} // namespace

unsigned timeLimitOf(const Export& study) {
  static const NumberRule rule{"time_limit", "EXPORT_9", "one positive number of seconds",
                               "3600",       false,      [](double s) { return s > 0.0 && s <= 1.0e9; }};
  const auto seconds = numberParameter(study, rule);
  return seconds ? static_cast<unsigned>(std::ceil(*seconds)) : 0U;
}

double memoryLimitOf(const Export& study) {
  static const NumberRule rule{"memory_limit", "EXPORT_11", "one number of MiB of at least 64",
                               "4096",         false,       [](double m) { return m >= 64.0 && m <= 1.0e9; }};
  return numberParameter(study, rule).value_or(0.0);
}

int cpusOf(const Export& study) {
  static const NumberRule rule{"ncpus", "EXPORT_10", "one whole number of threads from 1 to 1024",
                               "2",     true,        [](double n) { return n >= 1.0 && n <= 1024.0; }};
  return static_cast<int>(numberParameter(study, rule).value_or(1.0));
}

int mpiProcessesOf(const Export& study) {
  static const NumberRule rule{"mpi_nbcpu", "EXPORT_12", "one whole number of MPI processes from 1 to 1024",
                               "2",         true,        [](double n) { return n >= 1.0 && n <= 1024.0; }};
  return static_cast<int>(numberParameter(study, rule).value_or(1.0));
}

} // namespace stella
