// `stella sweep`: one study over a grid of parameter values, timed and measured (doc/sweep.md).

#include "Commands.hpp"
#include "tools/sweep/ChildProcess.hpp"
#include "tools/sweep/SweepRunner.hpp"
#include "tools/sweep/SweepSpec.hpp"
#include "tools/sweep/SweepTable.hpp"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace stella::cli {

namespace fs = std::filesystem;
using namespace stella::sweep;

namespace {

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    throw SweepError("cannot read " + file.string());
  }
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

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return one.empty() ? std::string("unknown") : one;
}

SweepSpec specOf(const SweepArguments& args) {
  const fs::path target = fs::absolute(args.target).lexically_normal();
  SweepSpec spec;
  if (target.extension() == ".export") {
    spec.study = target;
  } else {
    spec = parseSweepFile(readText(target), target);
  }
  for (const auto& v : args.vary) {
    addVary(spec, v);
  }
  if (args.repeats > 0) {
    spec.repeats = args.repeats;
  }
  if (!args.error.empty()) {
    spec.error = args.error;
  }
  validate(spec);
  return spec;
}

fs::path defaultOutput(const SweepArguments& args) {
  const fs::path target = fs::absolute(args.target);
  return target.parent_path() / (target.stem().string() + "_sweep");
}

// sweep.md and sweep.png from the table (sweep.csv is written before); returns false when the
// figure could not be drawn.
bool writeReport(Table& table, const fs::path& dir, const std::string& preamble, bool plot) {
  const auto front = markParetoFront(table);
  writeText(dir / "sweep.csv", toCsv(table));
  writeText(dir / "sweep.md", preamble + "\n" + toMarkdown(table, front));
  std::cerr << "stella: wrote " << (dir / "sweep.csv").string() << "\nstella: wrote "
            << (dir / "sweep.md").string() << "\n";
  if (!plot) {
    return true;
  }
  const char* script = std::getenv("STELLA_SWEEP_PLOT");
  const char* python = std::getenv("STELLA_PYTHON");
  const std::vector<std::string> argv{python != nullptr ? python : "/usr/bin/python3",
                                      script != nullptr ? script : STELLA_SWEEP_PLOT_SCRIPT,
                                      (dir / "sweep.csv").string(), (dir / "sweep.png").string()};
  const ChildOutcome drawn = runChild(argv, fs::path(), dir / "sweep_plot.log", 300.0);
  if (drawn.exitCode != 0) {
    std::cerr << "stella: the figure was not drawn: " << argv[0] << " " << argv[1] << " failed (see "
              << (dir / "sweep_plot.log").string() << "); the CSV and Markdown tables are written\n";
    return false;
  }
  std::cerr << "stella: wrote " << (dir / "sweep.png").string() << "\n";
  return true;
}

int report(const SweepArguments& args) {
  const fs::path dir = args.report;
  Table table = fromCsv(readText(dir / "sweep.csv"));
  // The words before the table (the command and the machine's load) stay those of the sweep.
  const std::string note = "Tables and figure redrawn from `sweep.csv` by `stella sweep --report`.\n";
  std::string preamble = note;
  if (fs::exists(dir / "sweep.md")) {
    const std::string before = readText(dir / "sweep.md");
    const auto start = before.find("\n| run |");
    if (start != std::string::npos) {
      preamble = before.substr(0, start);
      preamble += preamble.find(note) == std::string::npos ? "\n" + note : std::string();
    }
  }
  return writeReport(table, dir, preamble, !args.noPlot) ? 0 : 3;
}

} // namespace

int sweep(const SweepArguments& args) {
  try {
    if (!args.report.empty()) {
      return report(args);
    }
    const SweepSpec spec = specOf(args);
    RunnerOptions options;
    options.stella = fs::read_symlink("/proc/self/exe");
    options.outputDir = fs::absolute(args.outputDir.empty() ? defaultOutput(args) : fs::path(args.outputDir));
    options.jobs = args.jobs;
    options.keepRuns = args.keepRuns;
    options.progress = &std::cerr;
    options.terminal = isatty(STDERR_FILENO) != 0;
    const std::string loadBefore = loadAverage();
    Table table = runSweep(spec, options);
    std::ostringstream preamble;
    preamble << "Written by `" << args.commandLine << "` (study " << spec.study.filename().string() << ", "
             << spec.repeats << " repeat(s), median shown, -j " << args.jobs << "; "
             << std::thread::hardware_concurrency() << " cores, load average " << loadBefore << " before and "
             << loadAverage() << " after).\n";
    if (sweepInterrupted()) {
      preamble << "\n**Interrupted**: the runs not made are marked NOT_RUN.\n";
    }
    const bool drawn = writeReport(table, options.outputDir, preamble.str(), !args.noPlot);
    if (sweepInterrupted()) {
      std::cerr << "stella sweep: interrupted; the table holds the runs made\n";
      return 6; // as `stella run`: <S>_INTERRUPTED
    }
    return drawn ? 0 : 3;
  } catch (const SweepError& e) {
    std::cerr << "stella sweep: " << e.what() << "\n";
    return exitInput;
  } catch (const std::exception& e) {
    std::cerr << "stella sweep: " << e.what() << "\n";
    return exitInput;
  }
}

} // namespace stella::cli
