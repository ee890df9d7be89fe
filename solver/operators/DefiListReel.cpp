// DEFI_LIST_REEL: a list of reals, given (VALE) or built by intervals from DEBUT
// (INTERVALLE=_F(JUSQU_A=..., NOMBRE=... or PAS=...)).

#include "interpreter/Diagnostics.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

void appendInterval(const KeywordTree& interval, std::vector<double>& values) {
  double from = values.back();
  double to = interval.real("JUSQU_A");
  if (!(to > from)) {
    throw UserError(Diagnostic::fatal("LIST_1", fmt::format("JUSQU_A = {} does not follow {}", to, from),
                                      interval.locationOf("JUSQU_A")));
  }
  std::int64_t count = 0;
  if (interval.has("NOMBRE")) {
    count = interval.integer("NOMBRE");
  } else {
    double step = interval.real("PAS");
    double n = (to - from) / step;
    count = std::llround(n);
    if (step <= 0 || count < 1 || std::fabs(n - static_cast<double>(count)) > 1.0e-6 * std::max(1.0, n)) {
      throw UserError(
          Diagnostic::fatal("LIST_2",
                            fmt::format("PAS = {} does not divide the interval [{}, {}] into a whole "
                                        "number of steps",
                                        step, from, to),
                            interval.locationOf("PAS"))
              .withNote("use NOMBRE, or a step that divides the interval"));
    }
  }
  if (count < 1) {
    throw UserError(Diagnostic::fatal("LIST_3", "NOMBRE must be at least 1", interval.locationOf("NOMBRE")));
  }
  for (std::int64_t i = 1; i <= count; ++i) {
    values.push_back(i == count ? to
                                : from + (to - from) * static_cast<double>(i) / static_cast<double>(count));
  }
}

Value runDefiListReel(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  std::vector<double> values;
  if (kw.has("VALE")) {
    values = kw.reals("VALE");
    for (std::size_t i = 1; i < values.size(); ++i) {
      if (!(values[i] > values[i - 1])) { // also refuses nan
        throw UserError(Diagnostic::fatal("LIST_4",
                                          fmt::format("VALE must increase strictly: value {} ({}) follows "
                                                      "value {} ({})",
                                                      i + 1, values[i], i, values[i - 1]),
                                          kw.locationOf("VALE"))
                            .withNote("code_aster refuses a list of reals that does not increase; sort the "
                                      "values and remove the repeated ones"));
      }
    }
  } else {
    values.push_back(kw.real("DEBUT"));
    for (const KeywordTree& interval : kw.occurrences("INTERVALLE")) {
      appendInterval(interval, values);
    }
  }
  return call.makeConcept(std::make_shared<RealList>(std::move(values)));
}

} // namespace

STELLA_OPERATOR("DEFI_LIST_REEL", runDefiListReel);

} // namespace stella
