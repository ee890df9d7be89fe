// ArchiveSelection: PAS_ARCH or a list of instants.

#include "solver/nonlinear/Archiving.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <cmath>

namespace stella {

ArchiveSelection ArchiveSelection::every(int step) {
  ArchiveSelection s;
  s.every_ = step;
  return s;
}

ArchiveSelection ArchiveSelection::at(std::vector<double> times, double precision, bool absolute) {
  ArchiveSelection s;
  s.every_ = 0;
  s.times_ = std::move(times);
  s.precision_ = precision;
  s.absolute_ = absolute;
  return s;
}

ArchiveSelection ArchiveSelection::read(const KeywordTree& statNonLine) {
  if (!statNonLine.has("ARCHIVAGE")) {
    return every(1);
  }
  const KeywordTree& a = statNonLine.occurrences("ARCHIVAGE").front();
  const double precision = a.realOr("PRECISION", 1.0e-6);
  const bool absolute = a.textOr("CRITERE", "RELATIF") == "ABSOLU";
  if (a.has("INST")) {
    return at(a.reals("INST"), precision, absolute);
  }
  if (a.has("LIST_INST")) {
    auto list = conceptData<RealList>(a.conceptValue("LIST_INST"));
    STELLA_ASSERT(list != nullptr, "ARCHIVAGE/LIST_INST holds no list of reals");
    return at(list->values, precision, absolute);
  }
  const auto step = a.integerOr("PAS_ARCH", 1);
  if (step < 1) {
    throw UserError(
        Diagnostic::fatal("SNL_6", "ARCHIVAGE PAS_ARCH must be at least 1", a.locationOf("PAS_ARCH")));
  }
  return every(static_cast<int>(step));
}

bool ArchiveSelection::selects(int index, double time) const {
  if (every_ > 0) {
    return index % every_ == 0;
  }
  const double tolerance = absolute_ ? precision_ : precision_ * std::fabs(time);
  for (double t : times_) {
    if (std::fabs(t - time) <= tolerance) {
      return true;
    }
  }
  return false;
}

} // namespace stella
