// The table of a sweep from what its runs recorded.

#include "SweepRecord.hpp"

#include <algorithm>

namespace stella::sweep {

double median(std::vector<double> values) {
  if (values.empty()) {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

namespace {

const std::vector<std::string> measureColumns{
    "status",       "finished",   "repeats",         "wall_s",         "cpu_s",
    "time_s",       "time_of",    "peak_mem_mb",     "steps",          "newton_iter",
    "contact_iter", "geom_iter",  "snl_numbering_s", "snl_assembly_s", "snl_factorisation_s",
    "snl_solve_s",  "snl_post_s", "snl_other_s",     "snl_total_s",    "error",
    "error_of"};

std::string seconds(double s) {
  return formatNumber(s, 4);
}

// The median over the finished repeats of what `of` reads in a repeat.
template <class F> double medianOf(const std::vector<Repeat>& repeats, F of) {
  std::vector<double> values;
  for (const auto& r : repeats) {
    if (r.finished || repeats.size() == 1) {
      values.push_back(of(r));
    }
  }
  return median(values);
}

void fillMeasures(Table& t, std::size_t row, const Point& p, const std::string& time) {
  if (!p.meshFailure.empty() || p.repeats.empty()) {
    t.set(row, "status", p.meshFailure.empty() ? "NOT_RUN" : p.meshFailure);
    t.set(row, "finished", "no");
    t.set(row, "repeats", "0");
    return;
  }
  const Repeat& first = p.repeats.front();
  const MessReport& m = first.report;
  t.set(row, "status", first.status);
  t.set(row, "finished", first.finished ? "yes" : "no");
  t.set(row, "repeats", std::to_string(p.repeats.size()));
  t.set(row, "wall_s", seconds(medianOf(p.repeats, [](const Repeat& r) { return r.child.wallSeconds; })));
  t.set(row, "cpu_s", seconds(medianOf(p.repeats, [](const Repeat& r) { return r.child.cpuSeconds; })));
  t.set(row, "time_s", t.at(row, time == "cpu" ? "cpu_s" : "wall_s"));
  t.set(row, "time_of", time);
  t.set(row, "peak_mem_mb",
        formatNumber(medianOf(p.repeats, [](const Repeat& r) { return r.child.peakMemoryMiB; }), 4));
  t.set(row, "steps", std::to_string(m.steps));
  t.set(row, "newton_iter", std::to_string(m.newtonIterations));
  t.set(row, "contact_iter", std::to_string(m.contactIterations));
  t.set(row, "geom_iter", std::to_string(m.geometricIterations));
  const std::vector<std::pair<std::string, double PhaseSums::*>> phases{
      {"snl_numbering_s", &PhaseSums::numbering},
      {"snl_assembly_s", &PhaseSums::assembly},
      {"snl_factorisation_s", &PhaseSums::factorisation},
      {"snl_solve_s", &PhaseSums::solve},
      {"snl_post_s", &PhaseSums::post},
      {"snl_other_s", &PhaseSums::other},
      {"snl_total_s", &PhaseSums::total}};
  for (const auto& [column, member] : phases) {
    t.set(row, column,
          seconds(medianOf(p.repeats, [member](const Repeat& r) { return r.report.phases.*member; })));
  }
}

// The error the figure shows: the named test's, or the largest of the run's reference tests.
void fillErrors(Table& t, std::size_t row, const Point& p, const std::string& chosen) {
  if (p.repeats.empty()) {
    return;
  }
  const MessReport& m = p.repeats.front().report;
  const ReferenceTest* shown = nullptr;
  for (const auto& test : m.tests) {
    t.set(row, "err:" + test.name, formatNumber(test.error, 6));
    if (chosen.empty() ? shown == nullptr || test.error > shown->error : test.name == chosen) {
      shown = &test;
    }
  }
  if (shown != nullptr && p.repeats.front().finished) {
    t.set(row, "error", formatNumber(shown->error, 6));
    t.set(row, "error_of", shown->name);
  }
}

} // namespace

Table buildTable(const SweepSpec& spec, const std::vector<Point>& points,
                 const std::filesystem::path& outputDir) {
  Table t;
  t.header = {"run", "series", "label"};
  for (const auto& c : parameterColumns(spec)) {
    t.header.push_back(c);
  }
  t.header.push_back("mesh_size");
  t.header.insert(t.header.end(), measureColumns.begin(), measureColumns.end());
  for (std::size_t row = 0; row < points.size(); ++row) {
    const Point& p = points[row];
    t.rows.emplace_back(t.header.size());
    t.set(row, "run", std::to_string(p.grid.index));
    t.set(row, "series", p.grid.series);
    t.set(row, "label", p.grid.label);
    for (const auto& [name, value] : p.grid.settings) {
      t.set(row, name, value);
      if (name == spec.meshSize) {
        t.set(row, "mesh_size", value);
      }
    }
    fillMeasures(t, row, p, spec.time);
    fillErrors(t, row, p, spec.error);
  }
  // err:* columns came in first-seen order; the run folder (kept for failed runs) and the front last.
  for (std::size_t row = 0; row < points.size(); ++row) {
    const bool kept = std::filesystem::exists(points[row].directory);
    t.set(row, "files", kept ? std::filesystem::relative(points[row].directory, outputDir).string() : "");
  }
  markParetoFront(t);
  return t;
}

} // namespace stella::sweep
