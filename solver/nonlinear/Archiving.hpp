#pragma once
// ARCHIVAGE of STAT_NON_LINE: which computed steps are stored in the result. As in code_aster
// the initial state and the last instant are always stored; PAS_ARCH=n stores every n-th
// computed instant (the instants added by step cutting count, they are part of the list);
// LIST_INST / INST store the instants found within PRECISION (CRITERE='RELATIF': relative to
// the instant, 'ABSOLU': absolute). A run that stops on a failure also stores its last
// converged step (see StatNonLine). The keywords are read by solver/inputs/ArchivingReader.

#include <vector>

namespace stella {

class ArchiveSelection {
public:
  // Every `step`-th computed instant (PAS_ARCH; 1 = all).
  static ArchiveSelection every(int step);
  // The instants of `times` within `precision` (relative unless `absolute`).
  static ArchiveSelection at(std::vector<double> times, double precision, bool absolute);
  // Whether the computed instant number `index` (1, 2, ...) at `time` is stored.
  bool selects(int index, double time) const;

private:
  int every_ = 1;
  std::vector<double> times_;
  double precision_ = 1.0e-6;
  bool absolute_ = false;
};

} // namespace stella
