// Running a sweep: preparation of each point's files, the pool of child runs, the table.

#include "SweepRunner.hpp"
#include "ChildProcess.hpp"
#include "SweepRecord.hpp"
#include "solver/job/Export.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <thread>

namespace stella::sweep {

namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) {
    throw SweepError("cannot write " + file.string());
  }
}

std::string flags(const ExportEntry& e) {
  return std::string(e.data ? "D" : "") + (e.result ? "R" : "");
}

// The export of one repeat: command files and mesh replaced, data paths absolute, results in `dir`.
std::string exportText(const Export& study, const std::vector<fs::path>& comms, const fs::path& mesh,
                       int meshUnit, const fs::path& dir) {
  std::string out = "# written by stella sweep from " + study.file.string() + "\n";
  for (const auto& [key, values] : study.parameters) {
    out += "P " + key;
    for (const auto& v : values) {
      out += " " + v;
    }
    out += "\n";
  }
  std::size_t comm = 0;
  for (const auto& e : study.entries) {
    fs::path path = e.path;
    if (e.type == "comm" && e.data && comm < comms.size()) {
      path = comms[comm++];
    } else if (e.data && !mesh.empty() && e.unit == meshUnit) {
      path = mesh;
    } else if (e.result) {
      path = dir / e.path.filename();
    }
    out += std::string(e.directory ? "R " : "F ") + e.type + " " + path.string() + " " + flags(e) + " " +
           std::to_string(e.unit) + "\n";
  }
  return out;
}

// Ctrl-C or SIGTERM: no new run starts; the runs under way end (on Ctrl-C they are interrupted
// too, at their safe point) and the table holds what was done.
volatile std::sig_atomic_t stopRequested = 0;
extern "C" void requestStop(int) {
  stopRequested = 1;
}

// "0.42", "3.1", "220": seconds as a person reads them on a progress line.
std::string roundSeconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, s >= 10.0 ? "%.0f" : "%.2g", s);
  return buffer;
}

class Sweep {
public:
  Sweep(const SweepSpec& spec, const RunnerOptions& options)
      : spec_(spec), options_(options), study_(Export::read(spec.study)) {}
  Table run();

private:
  void prepare();
  fs::path meshFor(const RunPoint& point, std::set<std::string>& used, std::string& failure);
  void prepareFiles(Point& point, std::set<std::string>& used);
  const Series* seriesOf(const RunPoint& point) const;
  void prepareExternal(Point& point, const Series& series);
  std::vector<std::string> command(const Point& point, int repeat) const;
  Repeat collect(const Point& point, int repeat, const ChildOutcome& child) const;
  Repeat collectExternal(const Point& point, int repeat, const ChildOutcome& child) const;
  void progress(std::size_t done, std::size_t total, const std::string& last);

  const SweepSpec& spec_;
  const RunnerOptions& options_;
  Export study_;
  std::vector<Point> points_;
  std::map<std::string, fs::path> meshes_;
  std::map<std::string, std::string> meshFailures_;
  fs::path messName_;
  double started_ = 0.0;
};

fs::path Sweep::meshFor(const RunPoint& point, std::set<std::string>& used, std::string& failure) {
  if (spec_.meshCommand.empty()) {
    return {};
  }
  const ExportEntry* entry = nullptr;
  for (const auto& e : study_.entries) {
    entry = e.data && e.unit == spec_.meshUnit ? &e : entry;
  }
  if (entry == nullptr) {
    throw SweepError("mesh_unit " + std::to_string(spec_.meshUnit) + " is no data unit of " +
                     spec_.study.string() + ": the generated mesh replaces the export's file of that unit");
  }
  const std::string key = substituteBraces(spec_.meshCommand, point.settings, "", used);
  if (meshes_.count(key) != 0) {
    failure = meshFailures_[key];
    return meshes_[key];
  }
  const fs::path file = options_.outputDir / "meshes" /
                        ("mesh_" + std::to_string(meshes_.size() + 1) + entry->path.extension().string());
  const std::string command = substituteBraces(spec_.meshCommand, point.settings, file.string(), used);
  const fs::path folder = spec_.file.empty() ? spec_.study.parent_path() : spec_.file.parent_path();
  fs::create_directories(file.parent_path());
  fs::remove(file); // a mesh of an earlier sweep in this folder is never taken for this one
  const fs::path log = file.string() + ".log";
  writeText(file.string() + ".command", command + "\n");
  const ChildOutcome made = runChild({"/bin/sh", "-c", command}, folder, log, spec_.timeout);
  if (made.exitCode != 0 || !fs::exists(file)) {
    meshFailures_[key] = "MESH_FAILED";
    if (options_.progress != nullptr) {
      *options_.progress << "sweep: the mesh command failed (" << log.string() << "): " << command << "\n";
    }
  }
  failure = meshFailures_[key];
  meshes_[key] = file;
  return file;
}

void Sweep::prepareFiles(Point& point, std::set<std::string>& used) {
  fs::create_directories(point.directory);
  std::vector<fs::path> comms;
  for (const ExportEntry* e : study_.commandFiles()) {
    const fs::path source = comms.empty() && !spec_.comm.empty() ? spec_.comm : e->path;
    const fs::path target = point.directory / source.filename();
    writeText(target, substituteAssignments(readText(source), point.grid.settings, used));
    comms.push_back(target);
  }
  for (int r = 0; r < spec_.repeats; ++r) {
    const fs::path dir = point.directory / ("r" + std::to_string(r + 1));
    fs::create_directories(dir);
    writeText(dir / "run.export", exportText(study_, comms, point.mesh, spec_.meshUnit, dir));
  }
}

void Sweep::prepare() {
  for (const auto& e : study_.entries) {
    messName_ = e.result && e.unit == 6 ? e.path.filename() : messName_;
  }
  if (messName_.empty()) {
    throw SweepError(spec_.study.string() + " declares no message file (a line 'F mess NAME R 6'): the "
                                            "sweep reads the iterations and the tests there");
  }
  for (const auto& grid : expandGrid(spec_)) {
    Point point{grid, {}, {}, {}, {}, {}};
    char name[16];
    std::snprintf(name, sizeof name, "%03d", grid.index);
    point.directory = options_.outputDir / "runs" / name;
    std::set<std::string> used;
    point.mesh = meshFor(grid, used, point.meshFailure);
    const Series* series = seriesOf(grid);
    if (series != nullptr && !series->command.empty()) {
      prepareExternal(point, *series);
      points_.push_back(std::move(point));
      continue; // its [vary] values are the stella series' too: they are checked there
    }
    prepareFiles(point, used);
    for (const auto& [param, value] : grid.settings) {
      if (!value.empty() && used.count(param) == 0) {
        throw SweepError("parameter " + param + " is set (" + value +
                         ") but no command file assigns it on a line of its own before DEBUT() ('" + param +
                         " = ...' at the start of a line) and the mesh command does not use {" + param + "}");
      }
    }
    points_.push_back(std::move(point));
  }
}

const Series* Sweep::seriesOf(const RunPoint& point) const {
  for (const auto& s : spec_.series) {
    if (s.name == point.series) {
      return &s;
    }
  }
  return nullptr;
}

// {out} is marked here and replaced per repeat (command()); {NAME} and {mesh} are replaced now.
const std::string outMark = "\x01out\x01";

std::string replaceAll(std::string text, const std::string& what, const std::string& by) {
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + by.size())) {
    text.replace(at, what.size(), by);
  }
  return text;
}

void Sweep::prepareExternal(Point& point, const Series& series) {
  std::set<std::string> used;
  point.external =
      substituteBraces(replaceAll(series.command, "{out}", outMark), point.grid.settings,
                       point.mesh.empty() ? std::string() : fs::absolute(point.mesh).string(), used);
  for (int r = 0; r < spec_.repeats; ++r) {
    const fs::path dir = point.directory / ("r" + std::to_string(r + 1));
    fs::create_directories(dir);
    writeText(dir / "command",
              replaceAll(point.external, outMark, fs::absolute(dir / "out").string()) + "\n");
  }
}

std::vector<std::string> Sweep::command(const Point& point, int repeat) const {
  const fs::path dir = point.directory / ("r" + std::to_string(repeat + 1));
  if (!point.external.empty()) {
    return {"/bin/sh", "-c", replaceAll(point.external, outMark, fs::absolute(dir / "out").string())};
  }
  return {options_.stella.string(), "run", (dir / "run.export").string(), "--quiet", "--work-dir",
          (dir / "work").string()};
}

Repeat Sweep::collect(const Point& point, int repeat, const ChildOutcome& child) const {
  if (!point.external.empty()) {
    return collectExternal(point, repeat, child);
  }
  Repeat r;
  r.child = child;
  const fs::path mess = point.directory / ("r" + std::to_string(repeat + 1)) / messName_;
  r.report = parseMessage(fs::exists(mess) ? readText(mess) : std::string());
  r.finished = !child.timedOut && (child.exitCode == 0 || child.exitCode == 1);
  if (child.timedOut) {
    r.status = "TIMEOUT";
  } else if (child.signal != 0) {
    r.status = "CRASH (signal " + std::to_string(child.signal) + ")";
  } else if (!r.report.diagnostic.empty()) {
    r.status = r.report.diagnostic;
  } else {
    r.status = "exit " + std::to_string(child.exitCode);
  }
  return r;
}

// An external run ended well when it exited with 0 and wrote at least one test to {out}.
Repeat Sweep::collectExternal(const Point& point, int repeat, const ChildOutcome& child) const {
  Repeat r;
  r.child = child;
  const fs::path out = point.directory / ("r" + std::to_string(repeat + 1)) / "out";
  if (child.timedOut) {
    r.status = "TIMEOUT";
  } else if (child.signal != 0) {
    r.status = "CRASH (signal " + std::to_string(child.signal) + ")";
  } else if (child.exitCode != 0) {
    r.status = "exit " + std::to_string(child.exitCode);
  } else {
    try {
      r.report = parseExternalResult(fs::exists(out) ? readText(out) : std::string());
      r.finished = !r.report.tests.empty();
      r.status = r.finished ? "OK" : "NO_RESULT";
    } catch (const SweepError& e) {
      r.status = "BAD_RESULT";
      writeText(out.string() + ".error", out.string() + ":" + e.what() + "\n");
    }
  }
  return r;
}

void Sweep::progress(std::size_t done, std::size_t total, const std::string& last) {
  if (options_.progress == nullptr) {
    return;
  }
  const double elapsed = monotonicSeconds() - started_;
  const double left =
      done == 0 ? 0.0 : elapsed / static_cast<double>(done) * static_cast<double>(total - done);
  std::string line = "sweep: " + std::to_string(done) + "/" + std::to_string(total) + " runs, elapsed " +
                     roundSeconds(elapsed) + " s, about " + roundSeconds(left) + " s left; " + last;
  *options_.progress << (options_.terminal ? "\r\033[K" : "") << line << (options_.terminal ? "" : "\n")
                     << std::flush;
}

Table Sweep::run() {
  started_ = monotonicSeconds();
  prepare();
  struct Task {
    std::size_t point;
    int repeat;
  };
  std::vector<Task> tasks;
  for (std::size_t p = 0; p < points_.size(); ++p) {
    for (int r = 0; r < spec_.repeats; ++r) {
      tasks.push_back({p, r});
    }
  }
  // A point whose mesh failed is not run; one whose first run failed is not repeated, and its
  // other runs wait for the first (so that -j N does not start them beside it).
  enum : char { pending, started, skipped };
  std::vector<char> state(tasks.size(), pending);
  std::size_t total = tasks.size();
  auto skipRest = [&](std::size_t point) {
    for (std::size_t j = 0; j < tasks.size(); ++j) {
      if (tasks[j].point == point && state[j] == pending) {
        state[j] = skipped;
        --total;
      }
    }
  };
  for (std::size_t p = 0; p < points_.size(); ++p) {
    if (points_[p].failed()) {
      skipRest(p);
    }
  }
  auto anyPending = [&] { return std::find(state.begin(), state.end(), pending) != state.end(); };
  std::size_t done = 0;
  std::vector<std::pair<Task, std::unique_ptr<Child>>> active;
  bool told = false;
  while ((anyPending() && stopRequested == 0) || !active.empty()) {
    if (stopRequested != 0 && !told && options_.progress != nullptr) {
      *options_.progress << "\nsweep: interrupted: no new run; waiting for the " << active.size()
                         << " run(s) under way, then writing the table\n";
      told = true;
    }
    for (std::size_t k = 0; k < tasks.size() && stopRequested == 0 &&
                            static_cast<int>(active.size()) < std::max(1, options_.jobs);
         ++k) {
      const Task t = tasks[k];
      const Point& point = points_[t.point];
      if (state[k] != pending || (t.repeat > 0 && point.repeats.empty())) {
        continue;
      }
      state[k] = started;
      const fs::path dir = point.directory / ("r" + std::to_string(t.repeat + 1));
      // An external command runs in the sweep file's folder, as the mesh command does.
      const fs::path folder = point.external.empty() ? fs::path()
                              : spec_.file.empty()   ? spec_.study.parent_path()
                                                     : spec_.file.parent_path();
      active.emplace_back(t, std::make_unique<Child>(command(point, t.repeat), folder,
                                                     dir / (point.external.empty() ? "stella.log" : "log"),
                                                     spec_.timeout));
    }
    for (auto it = active.begin(); it != active.end();) {
      if (!it->second->poll()) {
        ++it;
        continue;
      }
      Point& point = points_[it->first.point];
      Repeat r = collect(point, it->first.repeat, it->second->outcome());
      ++done;
      if (!r.finished) {
        skipRest(it->first.point);
      }
      progress(done, total,
               point.grid.label + " (" + std::to_string(it->first.repeat + 1) + "/" +
                   std::to_string(spec_.repeats) + "): " + r.status + " " +
                   formatNumber(r.child.wallSeconds, 3) + " s");
      point.repeats.push_back(std::move(r));
      it = active.erase(it);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (stopRequested != 0 && !told && options_.progress != nullptr) {
    // the signal came between two runs (none under way): said here, the loop ended at once
    *options_.progress << "\nsweep: interrupted: no new run; writing the table\n";
  }
  if (options_.progress != nullptr && options_.terminal) {
    *options_.progress << "\n";
  }
  if (!options_.keepRuns) {
    for (const auto& p : points_) {
      if (!p.failed()) {
        fs::remove_all(p.directory);
      }
    }
  }
  return buildTable(spec_, points_, options_.outputDir);
}

} // namespace

Table runSweep(const SweepSpec& spec, const RunnerOptions& options) {
  fs::create_directories(options.outputDir / "runs");
  Sweep sweep(spec, options);
  stopRequested = 0;
  struct sigaction stop {};
  stop.sa_handler = requestStop;
  sigemptyset(&stop.sa_mask);
  struct sigaction oldInt {};
  struct sigaction oldTerm {};
  sigaction(SIGINT, &stop, &oldInt);
  sigaction(SIGTERM, &stop, &oldTerm);
  Table table = sweep.run();
  sigaction(SIGINT, &oldInt, nullptr);
  sigaction(SIGTERM, &oldTerm, nullptr);
  return table;
}

bool sweepInterrupted() {
  return stopRequested != 0;
}

} // namespace stella::sweep
