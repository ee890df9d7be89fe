// DEFI_LIST_REEL: a list of reals, given (VALE) or built by intervals from DEBUT
// (INTERVALLE=_F(JUSQU_A=..., NOMBRE=... or PAS=...)).

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
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
    throw UserError(msg::make("LIST_1", {{"to", to}, {"from", from}}, interval.locationOf("JUSQU_A")));
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
          msg::make("LIST_2", {{"step", step}, {"from", from}, {"to", to}}, interval.locationOf("PAS")));
    }
  }
  if (count < 1) {
    throw UserError(msg::make("LIST_3", {}, interval.locationOf("NOMBRE")));
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
        throw UserError(msg::make(
            "LIST_4", {{"i", i + 1}, {"values", values[i]}, {"i_2", i}, {"values_2", values[i - 1]}},
            kw.locationOf("VALE")));
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
