#pragma once
// What a sweep recorded for each point of its grid, and the table made of it.

#include "ChildProcess.hpp"
#include "MessReport.hpp"
#include "SweepGrid.hpp"
#include "SweepTable.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace stella::sweep {

struct Repeat {
  ChildOutcome child;
  MessReport report;
  std::string status;    // the job diagnostic, TIMEOUT, CRASH (signal N), exit N
  bool finished = false; // ended with its tests evaluated (exit 0 or 1)
};

struct Point {
  RunPoint grid;
  std::filesystem::path directory;
  std::filesystem::path mesh; // empty: the export's own mesh
  std::string meshFailure;
  std::string external; // an external series: its command, {out} still to replace per repeat
  std::vector<Repeat> repeats;
  bool failed() const { return !meshFailure.empty() || (!repeats.empty() && !repeats.front().finished); }
};

// One row per point: parameters, status, medians of the repeats' times and memory, iterations and
// errors of the first repeat, the error the figure shows, and the Pareto front.
Table buildTable(const SweepSpec& spec, const std::vector<Point>& points,
                 const std::filesystem::path& outputDir);

double median(std::vector<double> values);

} // namespace stella::sweep
