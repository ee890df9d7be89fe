#include "BatchJob.hpp"
#include "ExportParameters.hpp"
#include "JobSpec.hpp"

#include "CopyBack.hpp"
#include "TeeStream.hpp"
#include "catalog/Catalog.hpp"
#include "interpreter/Interpreter.hpp"
#include "messages/Messages.hpp"
#include "solver/linalg/BlasThreads.hpp"
#include "solver/parallel/Mpi.hpp"
#include "solver/session/ExceptionDiagnostic.hpp"
#include "solver/session/MemoryLimit.hpp"
#include "solver/session/Session.hpp"
#include "solver/session/StopRequest.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <unistd.h>

namespace stella {

namespace fs = std::filesystem;

namespace {

constexpr const char* workMarker = ".stella-work";

fs::path makeWorkDirectory(const RunOptions& options) {
  if (!options.workDirectory.empty()) {
    // Only a directory stella made itself (it holds the marker) is emptied: a mistyped
    // --work-dir must never delete a user's files.
    const fs::path& dir = options.workDirectory;
    if (fs::exists(dir) && !fs::is_empty(dir)) {
      if (!fs::exists(dir / workMarker)) {
        throw UserError(msg::make("RUN_4", {{"dir", dir.string()}}));
      }
      fs::remove_all(dir);
    }
    fs::create_directories(dir);
    std::ofstream(dir / workMarker) << "work directory of a stella run; emptied by the next run\n";
    return fs::absolute(dir);
  }
  std::string pattern = (fs::temp_directory_path() / "stella-run-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    throw UserError(msg::make("RUN_1", {{"temp_directory_path", fs::temp_directory_path().string()}}));
  }
  return fs::path(pattern);
}

std::string hostName() {
  char buffer[256] = {};
  if (gethostname(buffer, sizeof(buffer) - 1) != 0) {
    return "unknown";
  }
  return buffer;
}

std::string now() {
  std::time_t t = std::time(nullptr);
  char buffer[64] = {};
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%d %H:%M:%S", std::localtime(&t));
  return buffer;
}

void writeHeader(std::ostream& mess, const RunOptions& options, const fs::path& work) {
  mess << std::string(72, '=') << "\n"
       << "-- STELLA -- VERSION " << STELLA_VERSION << "\n"
       << "   date          : " << now() << "\n"
       << "   host          : " << hostName() << "\n"
       << "   command line  : " << options.commandLine << "\n"
       << "   work directory: " << work.string() << "\n"
       << (mpi::built() ? fmt::format("   MPI processes: {}{}\n", mpi::size(), mpi::partitioningNote()) : "")
       << std::string(72, '=') << "\n";
}

void writeTimingSummary(std::ostream& mess, const Session& session) {
  const auto& timings = session.timings();
  if (timings.empty()) {
    return;
  }
  double total = 0.0;
  for (const auto& t : timings) {
    total += t.seconds;
  }
  mess << "\n  Time per command (elapsed seconds)\n"
       << fmt::format("  {:<5} {:<22} {:<40} {:>10} {:>7}\n", "#", "command", "location", "seconds", "share");
  int n = 0;
  for (const auto& t : timings) {
    ++n;
    double share = total > 0 ? 100.0 * t.seconds / total : 0.0;
    mess << fmt::format("  {:<5} {:<22} {:<40} {:>10.3f} {:>6.1f}%\n", n, t.command, t.location, t.seconds,
                        share);
  }
  mess << fmt::format("  {:<5} {:<22} {:<40} {:>10.3f}\n", "", "total", "", total);
}

// A result file that could not be copied back: named, with the reason, in the message file.
struct CopyFailure {
  int unit;
  fs::path source; // in the work directory
  fs::path destination;
  std::string reason;
};

struct CopyOutcome {
  std::vector<fs::path> written;
  std::vector<CopyFailure> failed;
};

// Files a writer puts beside a unit (the .vtu of each step next to the .pvd of unit 81 are
// fort.81_<k>.vtu): copied next to the result as <result stem>_<k>.vtu, and the unit's file, which
// names them, rewritten to match.
void copyCompanions(const fs::path& work, int unit, const fs::path& destination, CopyOutcome& outcome) {
  const std::string prefix = fmt::format("fort.{}_", unit);
  const std::string stem = destination.stem().string() + "_";
  bool any = false;
  for (const auto& entry : fs::directory_iterator(work)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || name.rfind(prefix, 0) != 0) {
      continue;
    }
    const fs::path target = destination.parent_path() / (stem + name.substr(prefix.size()));
    if (auto reason = copyResultFile(entry.path(), target)) {
      outcome.failed.push_back({unit, entry.path(), target, *reason});
      continue;
    }
    outcome.written.push_back(target);
    any = true;
  }
  if (!any) {
    return;
  }
  std::string text;
  {
    std::ifstream in(destination, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::string quotedPrefix = "\"" + prefix;
  for (std::size_t at = text.find(quotedPrefix); at != std::string::npos; at = text.find(quotedPrefix, at)) {
    text.replace(at + 1, prefix.size(), stem);
    at += 1 + stem.size();
  }
  std::ofstream(destination, std::ios::binary) << text;
}

// Whether two files hold the same bytes (sizes first, then the contents in blocks).
bool sameContent(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::file_size(a, ec) != fs::file_size(b, ec) || ec) {
    return false;
  }
  std::ifstream fa(a, std::ios::binary);
  std::ifstream fb(b, std::ios::binary);
  std::vector<char> ba(1 << 16);
  std::vector<char> bb(1 << 16);
  while (fa && fb) {
    fa.read(ba.data(), static_cast<std::streamsize>(ba.size()));
    fb.read(bb.data(), static_cast<std::streamsize>(bb.size()));
    if (fa.gcount() != fb.gcount() || !std::equal(ba.begin(), ba.begin() + fa.gcount(), bb.begin())) {
      return false;
    }
  }
  return true;
}

// A quick run's `--unit N=path` is both a data file (copied in when it exists) and a result (copied
// back when the study wrote it): a unit whose file is still the data copied in was only read.
bool unchangedData(const JobSpec& spec, int unit, const fs::path& produced) {
  for (const auto& d : spec.data) {
    if (d.unit == unit) {
      return !d.directory && fs::exists(d.source) && sameContent(d.source, produced);
    }
  }
  return false;
}

// Copies the result units back, each file on its own: one that cannot be copied is recorded with
// its reason and the others still come back.
CopyOutcome copyResults(const JobSpec& spec, const fs::path& work, bool stopped, std::ostream& mess) {
  CopyOutcome outcome;
  for (const auto& [unit, destination] : spec.results) {
    if (unit == 6 || unit == 8) {
      continue; // still open: copied when the run is over
    }
    fs::path produced = work / ("fort." + std::to_string(unit));
    if (!fs::exists(produced) || (spec.resultsOptional && unchangedData(spec, unit, produced))) {
      if (spec.resultsOptional) {
        continue;
      }
      mess << (stopped
                   ? fmt::format("  unit {} ({}) was not written: the run stopped before the command that "
                                 "writes it\n",
                                 unit, destination.string())
                   : fmt::format("  unit {} ({}) was not written by the study\n", unit,
                                 destination.string()));
      continue;
    }
    if (auto reason = copyResultFile(produced, destination)) {
      outcome.failed.push_back({unit, produced, destination, *reason});
      continue;
    }
    outcome.written.push_back(destination);
    copyCompanions(work, unit, destination, outcome);
  }
  return outcome;
}

// The MED files of the steps of failed commands (Session::keepPartialResult).
void copyKeptFiles(const Session& session, CopyOutcome& outcome) {
  for (const KeptFile& kept : session.keptFiles()) {
    if (auto reason = copyResultFile(kept.work, kept.destination)) {
      outcome.failed.push_back({0, kept.work, kept.destination, *reason});
      continue;
    }
    outcome.written.push_back(kept.destination);
  }
}

// The message and result files (units 6 and 8) are copied when the run is over; a first copy of
// what they hold so far finds a destination that cannot be written while the message file can
// still say so.
void probeOpenUnits(const JobSpec& spec, const fs::path& work, CopyOutcome& outcome) {
  for (int unit : {6, 8}) {
    auto it = spec.results.find(unit);
    if (it == spec.results.end()) {
      continue;
    }
    const fs::path produced = work / ("fort." + std::to_string(unit));
    if (auto reason = copyResultFile(produced, it->second)) {
      outcome.failed.push_back({unit, produced, it->second, *reason});
    }
  }
}

Diagnostic copyFailure(const CopyFailure& f, const fs::path& work) {
  const std::string kept = f.source.filename().string();
  const std::string what = f.unit != 0 ? fmt::format("the result file of unit {}", f.unit)
                                       : "the MED file of the steps of the failed command";
  return msg::make("RUN_5", {{"what", what}, {"reason", f.reason}, {"work", work.string()}, {"kept", kept}});
}

// The data files of the export copied to their units; returns the paths of the units.
std::map<int, fs::path> copyData(const JobSpec& spec, const fs::path& work,
                                 std::vector<const JobSpec::DataFile*>& missing) {
  std::map<int, fs::path> unitPaths;
  for (const auto& d : spec.data) {
    fs::path target = work / ("fort." + std::to_string(d.unit));
    if (fs::exists(d.source)) {
      if (d.directory) {
        fs::copy(d.source, target, fs::copy_options::recursive);
      } else {
        fs::copy_file(d.source, target, fs::copy_options::overwrite_existing);
      }
    } else {
      missing.push_back(&d);
    }
    unitPaths[d.unit] = target;
  }
  return unitPaths;
}

// Runs the command files in one session; every exception ends as a framed diagnostic.
std::unique_ptr<Session> runStudy(const JobSpec& spec, const fs::path& work, std::ostream& mess,
                                  std::ostream& resuFile, const SessionOptions& sessionOptions,
                                  const RunOptions& options, std::vector<const JobSpec::DataFile*>& missing) {
  std::unique_ptr<Session> session;
  auto report = [&](const Diagnostic& d) {
    if (session) {
      session->report(d);
    } else {
      mess << formatDiagnostic(d);
    }
  };
  try {
    const std::map<int, fs::path> unitPaths = copyData(spec, work, missing);
    const Catalog& catalog = Catalog::builtin();
    session = std::make_unique<Session>(catalog, mess, resuFile, sessionOptions);
    for (const auto& [unit, path] : unitPaths) {
      session->declareUnit(unit, path);
    }
    for (const auto& d : spec.data) {
      session->declareUnitOrigin(d.unit, d.source);
    }
    for (const auto& [unit, destination] : spec.results) {
      session->declareResultUnit(unit);
    }
    InterpreterOptions budget;
    if (options.maxOperations > 0) {
      budget.operationBudget = options.maxOperations;
    }
    budget.memoryBudget = options.maxMemoryBytes;
    Interpreter interpreter(*session, *session, budget);
    for (const auto& name : catalog.commandNames()) {
      interpreter.defineCommand(name);
    }
    for (const auto& comm : spec.commandFiles) {
      mess << "\n  # Command file: " << comm.string() << "\n";
      RunStatus status = interpreter.run(SourceFile::load(comm.string()));
      if (status == RunStatus::SyntaxError || status == RunStatus::Failed) {
        break;
      }
    }
  } catch (const UserError& e) {
    for (const auto& d : e.diagnostics()) {
      report(d);
    }
  } catch (const std::exception& e) {
    report(diagnosticOf(e, msg::text("DURING.study")));
  }
  return session;
}

// What the session says at the end: missing data, the base, the timings, what was kept.
void closeSession(Session& session, const JobSpec& spec, const std::vector<const JobSpec::DataFile*>& missing,
                  const fs::path& work, std::ostream& mess) {
  for (const auto* d : missing) {
    const auto& opened = session.openedUnits();
    // A quick run's --unit that did not exist yet and that a command wrote is an output.
    const bool written = fs::exists(work / ("fort." + std::to_string(d->unit)));
    if (!written && std::find(opened.begin(), opened.end(), d->unit) == opened.end()) {
      session.report(
          msg::make("RUN_2", {{"source", d->source.string()}, {"unit", d->unit}, {"origin", d->origin}}));
    }
  }
  if (spec.saveBase) {
    session.report(msg::make("RUN_3"));
  }
  writeTimingSummary(mess, session);
}

// The diagnostic of a run process that ended on `signal`, with what usually causes it.
Diagnostic crashDiagnostic(int signal) {
  const char* name = sigabbrev_np(signal);
  Diagnostic d = msg::make("RUN_7", {{"signal", signal}, {"signal_name", name != nullptr ? name : "?"}});
  d.kind = FailureKind::Abort;
  if (signal == SIGKILL) {
    d.withNote(msg::text("RUN_7.n2"));
  } else {
    d.withNote(msg::text("RUN_7.n1"));
  }
  return d;
}

// The message and result files, complete only now, copied back; the work directory removed
// after a clean run.
void finishFiles(const JobSpec& spec, const RunOptions& options, const fs::path& work,
                 const CopyOutcome& copied, JobResult& job) {
  // The message and result files are complete only now.
  std::vector<fs::path> written = copied.written;
  for (int unit : {6, 8}) {
    auto it = spec.results.find(unit);
    if (it == spec.results.end()) {
      continue;
    }
    if (auto reason = copyResultFile(work / ("fort." + std::to_string(unit)), it->second)) {
      job.copyFailures.push_back(
          fmt::format("unit {}: {} (kept in {} as fort.{})", unit, *reason, work.string(), unit));
      continue;
    }
    written.push_back(it->second);
  }
  for (const auto& f : copied.failed) {
    if (f.unit != 6 && f.unit != 8) {
      job.copyFailures.push_back(fmt::format("unit {}: {} (kept in {} as {})", f.unit, f.reason,
                                             work.string(), f.source.filename().string()));
    }
  }
  job.resultFiles = written;
  bool failed = exitCode(job.diagnostic) != 0 || !job.copyFailures.empty();
  if (!options.keepWorkDirectory && !failed && options.workDirectory.empty()) {
    std::error_code ec;
    fs::remove_all(work, ec);
    job.workDirectory.clear();
  }
}

} // namespace

JobResult runInWork(const JobSpec& spec, const RunOptions& options, const fs::path& work) {
  JobResult job;
  job.workDirectory = work;

  std::ofstream messFile(work / "fort.6");
  std::ofstream resuFile(work / "fort.8");
  TeeBuffer tee(messFile.rdbuf(), options.echo ? std::cout.rdbuf() : nullptr);
  std::ostream mess(&tee);
  writeHeader(mess, options, work);

  SessionOptions sessionOptions;
  sessionOptions.referenceOnly = options.referenceOnly;
  sessionOptions.workDirectory = work;
  sessionOptions.cpus = spec.cpus;
  // The steps of a failed command go beside the message file, where the user looks first.
  const auto messDestination = spec.results.find(6);
  sessionOptions.keptResultsDirectory =
      messDestination != spec.results.end() ? messDestination->second.parent_path() : spec.outputDirectory;
  sessionOptions.keptResultsStem = spec.stem;
  installStopHandlers();
  clearStopRequest(); // a run in a process that ran another one (tests) starts afresh
  armTimeLimit(spec.timeLimit);

  std::vector<const JobSpec::DataFile*> missing;
  std::unique_ptr<Session> session;
  {
    ScopedMemoryLimit memoryLimit(spec.memoryLimit); // lifted before the copy-back
    if (spec.memoryLimit > 0.0) {
      mess << fmt::format("  Memory limit of the run: {:g} MiB (P memory_limit), beyond the program's own "
                          "address space of {:.0f} MiB at start\n",
                          spec.memoryLimit, memoryLimit.footprint());
    }
    mess << linalg::applyBlasThreads(spec.cpus); // P ncpus or STELLA_BLAS_THREADS
    session = runStudy(spec, work, mess, resuFile, sessionOptions, options, missing);
  }
  armTimeLimit(0); // the copy-back is not stopped

  SessionCounts counts;
  CopyOutcome copied;
  if (session) {
    session->reportDeferred(); // the run stopped before FIN: the held alarms still count
    try {
      closeSession(*session, spec, missing, work, mess);
      mess << "\n";
      copied = copyResults(spec, work, session->counts().failure != FailureKind::None, mess);
      copyKeptFiles(*session, copied);
      probeOpenUnits(spec, work, copied);
    } catch (const std::exception& e) {
      session->report(diagnosticOf(e, msg::text("DURING.copy_back")));
    }
    for (const auto& f : copied.failed) {
      session->report(copyFailure(f, work));
    }
    counts = session->counts();
    if (counts.failure != FailureKind::None) {
      mess << (counts.failure == FailureKind::Interrupted
                   ? "\n  The run was stopped. Every result computed before it is kept"
                   : "\n  The run ended on an error. Every result computed before it is kept");
      for (const auto& kept : session->keptResults()) {
        mess << "\n    " << kept;
      }
      mess << (copied.failed.empty()
                   ? "\n  and the result files declared for the run are copied back.\n"
                   : "\n  and the result files declared for the run are copied back, except "
                     "those named above.\n");
    }
  } else {
    counts.failure = FailureKind::Abort;
  }
  // --reference-only judges the file by its reference lines: none counted is NO_TEST_RESU.
  JobDiagnostic diagnostic = diagnose(counts, spec.isTestcase || options.referenceOnly);
  diagnostic = applyExpected(diagnostic, spec.expectedDiagnostics);
  job.diagnostic = diagnostic;

  if (exitCode(diagnostic) != 0 || options.keepWorkDirectory || !options.workDirectory.empty()) {
    mess << "\n  The work directory is kept: " << work.string() << "\n";
  }
  mess << "\n" << diagnosticFrame(diagnostic);
  mess.flush();
  messFile.close();
  resuFile.close();
  finishFiles(spec, options, work, copied, job);
  return job;
}

JobResult rescueCrashedRun(const JobSpec& spec, const RunOptions& options, const fs::path& work, int signal) {
  JobResult job;
  job.workDirectory = work;
  job.diagnostic = JobDiagnostic::AbnormalAbort;
  std::ofstream messFile(work / "fort.6", std::ios::app);
  TeeBuffer tee(messFile.rdbuf(), options.echo ? std::cout.rdbuf() : nullptr);
  std::ostream mess(&tee);
  mess << "\n" << framedDiagnostic(crashDiagnostic(signal));
  CopyOutcome copied;
  try {
    copied = copyResults(spec, work, true, mess);
  } catch (const std::exception& e) {
    mess << framedDiagnostic(diagnosticOf(e, msg::text("DURING.copy_back")));
  }
  for (const auto& f : copied.failed) {
    mess << framedDiagnostic(copyFailure(f, work));
  }
  mess << "\n  The run process ended abnormally. The result files the study wrote before are copied back"
       << (copied.failed.empty() ? "" : ", except those named above")
       << "; the steps of the command that was running are lost.\n"
       << "\n  The work directory is kept: " << work.string() << "\n"
       << "\n"
       << diagnosticFrame(job.diagnostic);
  mess.flush();
  messFile.close();
  finishFiles(spec, options, work, copied, job);
  return job;
}

namespace {

JobResult runSpec(const JobSpec& spec, const RunOptions& options) {
  if (mpi::built() && mpi::underLauncher()) { // a process of mpirun -n N: MpiRun.cpp
    const RunOptions own = rankOptions(options);
    return runOnRanks(spec, own, makeWorkDirectory(own));
  }
  fs::path work = makeWorkDirectory(options);
  return options.supervised ? runSupervised(spec, options, work) : runInWork(spec, options, work);
}

} // namespace

JobResult runExport(const Export& study, const RunOptions& options) {
  JobSpec spec;
  fs::path outputBase = options.outputDirectory.empty() ? study.file.parent_path() : options.outputDirectory;
  for (const auto& e : study.entries) {
    std::string origin = fmt::format("{}:{}", study.file.filename().string(), e.line);
    if (e.type == "comm" && e.data) {
      spec.commandFiles.push_back(e.path);
      continue;
    }
    if (e.type == "base" && e.result) {
      spec.saveBase = true;
      continue;
    }
    if (e.data && e.unit != 0) {
      spec.data.push_back({e.unit, e.path, origin, e.directory});
    }
    if (e.result && e.unit != 0) {
      fs::path p(e.pathAsWritten);
      spec.results[e.unit] = p.is_absolute() ? p : (outputBase / p).lexically_normal();
    }
  }
  spec.outputDirectory = outputBase;
  spec.stem = study.file.stem().string();
  spec.timeLimit = timeLimitOf(study);
  spec.memoryLimit = memoryLimitOf(study);
  spec.cpus = cpusOf(study);
  spec.isTestcase = study.hasParameter("testlist");
  spec.expectedDiagnostics = study.parameter("expected_diag");
  return runSpec(spec, options);
}

JobResult runCommandFile(const fs::path& commandFile, const std::map<int, fs::path>& units,
                         const RunOptions& options) {
  JobSpec spec;
  fs::path comm = fs::absolute(commandFile);
  spec.commandFiles.push_back(comm);
  fs::path outputBase = options.outputDirectory.empty() ? comm.parent_path() : options.outputDirectory;
  std::string stem = comm.stem().string();
  spec.results[6] = outputBase / (stem + ".mess");
  spec.results[8] = outputBase / (stem + ".resu");
  spec.results[80] = outputBase / (stem + ".rmed");
  spec.results[81] = outputBase / (stem + ".pvd"); // IMPR_RESU FORMAT='VTU', its .vtu beside it
  // Every other unit a command writes comes back as <stem>.<unit> (IMPR_TABLE on 30, GMSH on 37).
  for (int unit = 1; unit <= 99; ++unit) {
    if (unit != 15 && spec.results.count(unit) == 0) {
      spec.results[unit] = outputBase / fmt::format("{}.{}", stem, unit);
    }
  }
  // --unit N=path: read from path when it exists, and written back to it when a command wrote N.
  for (const auto& [unit, path] : units) {
    spec.data.push_back({unit, fs::absolute(path), fmt::format("--unit {}={}", unit, path.string()), false});
    spec.results[unit] = fs::absolute(path);
  }
  spec.resultsOptional = true;
  spec.outputDirectory = outputBase;
  spec.stem = stem;
  return runSpec(spec, options);
}

} // namespace stella
