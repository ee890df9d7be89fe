// PhaseTimes: peak memory and the phase lines of the message file.

#include "solver/nonlinear/PhaseTimes.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

namespace stella {

double peakResidentMegabytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) {
    return 0.0;
  }
  return static_cast<double>(usage.ru_maxrss) / 1024.0; // kilobytes on Linux
}

std::string formatPhases(const PhaseTimes& t, int analyses, std::size_t equations) {
  const double total = t.total();
  const double peak = peakResidentMegabytes();
  const double outside = t.numbering + t.assembly + t.post + t.other + t.contact;
  return fmt::format("   phases (s): numbering {:.3f}, assembly {:.3f}, factorisation {:.3f} ({} analysis), "
                     "solve {:.3f}, post {:.3f}{}{}; total {:.3f}, outside factorisation and solve {:.1f} %\n"
                     "   peak memory: {:.0f} MB{}\n",
                     t.numbering, t.assembly, t.factorisation, analyses, t.solve, t.post,
                     t.contact > 0.0 ? fmt::format(", contact {:.3f}", t.contact) : std::string(),
                     t.other > 0.0 ? fmt::format(", other {:.3f}", t.other) : std::string(), total,
                     total > 0.0 ? 100.0 * outside / total : 0.0, peak,
                     equations > 0 ? fmt::format(" ({:.2f} kB per equation, {} equations)",
                                                 peak * 1024.0 / static_cast<double>(equations), equations)
                                   : std::string());
}

} // namespace stella
