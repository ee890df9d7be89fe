// ArchiveSelection: PAS_ARCH or a list of instants.

#include "solver/nonlinear/Archiving.hpp"

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
