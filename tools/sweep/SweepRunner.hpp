#pragma once
// Running a sweep: the meshes, each point's files, the runs as child processes of stella (a run
// that fails, crashes or does not converge is a row of the table, never the end of the sweep),
// the progress line, and the table of medians.

#include "SweepSpec.hpp"
#include "SweepTable.hpp"

#include <filesystem>
#include <iosfwd>
#include <string>

namespace stella::sweep {

struct RunnerOptions {
  std::filesystem::path stella;    // the executable the runs use (this one)
  std::filesystem::path outputDir; // sweep.csv, sweep.md, sweep.png, meshes/, runs/
  int jobs = 1;
  bool keepRuns = false; // keep the files of runs that ended OK
  std::ostream* progress = nullptr;
  bool terminal = false; // rewrite the progress line in place
};

// Runs every point `spec.repeats` times (a point that fails is not repeated) and returns the
// table of medians. Throws SweepError for a sweep that cannot start (bad parameter, mesh failure).
// Ctrl-C or SIGTERM stop it: no new run starts, the runs under way end, the table holds what was
// done (points not run: status NOT_RUN) and sweepInterrupted() is true.
Table runSweep(const SweepSpec& spec, const RunnerOptions& options);
bool sweepInterrupted();

} // namespace stella::sweep
