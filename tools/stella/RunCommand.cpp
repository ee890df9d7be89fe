// `stella run`: a batch run from a .export, or a quick run of a .comm with --unit options.

#include "Commands.hpp"
#include "messages/Messages.hpp"
#include "solver/job/BatchJob.hpp"
#include "solver/job/Confine.hpp"
#include "solver/job/ExportParameters.hpp"
#include "solver/nonlinear/ProgressLine.hpp"
#include "solver/parallel/Launch.hpp"
#include "solver/parallel/Mpi.hpp"
#include "solver/session/ExceptionDiagnostic.hpp"

#include <charconv>
#include <iostream>
#include <unistd.h>

namespace stella::cli {

namespace {

// "20=mesh.med" -> (20, mesh.med); returns false when malformed.
bool parseUnit(const std::string& text, int& unit, std::string& path) {
  auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    return false;
  }
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + eq, unit);
  if (ec != std::errc() || ptr != text.data() + eq || unit < 1 || unit > 99 || unit == 6 || unit == 15) {
    return false;
  }
  path = text.substr(eq + 1);
  return true;
}

void printOutcome(const JobResult& job) {
  std::cerr << "stella: diagnostic " << diagnosticWord(job.diagnostic) << "\n";
  for (const auto& f : job.resultFiles) {
    std::cerr << "stella: wrote " << f.string() << "\n";
  }
  for (const auto& f : job.copyFailures) {
    std::cerr << "stella: NOT copied back: " << f << "\n";
  }
  if (!job.workDirectory.empty()) {
    std::cerr << "stella: work directory kept: " << job.workDirectory.string() << "\n";
  }
}

// P mpi_nbcpu N > 1 without mpirun: this stella again under mpirun -n N (doc/parallel.md).
int relaunch(const Export& study, int processes, const RunArguments& args) {
  if (!mpi::built()) {
    std::cerr << formatDiagnostic(
        msg::make("EXPORT_12.2", {{"processes", processes}, {"file", study.file.string()}}));
    return exitInput;
  }
  const std::string reason = mpi::relaunchUnderMpirun(processes, args.arguments);
  std::cerr << "stella: P mpi_nbcpu " << processes << ": " << reason << "\n";
  return exitInput;
}

} // namespace

int run(const RunArguments& args) {
  RunOptions options;
  options.workDirectory = args.workDirectory;
  options.outputDirectory = args.outputDirectory;
  options.referenceOnly = args.referenceOnly;
  options.keepWorkDirectory = args.keepWork;
  options.echo = !args.quiet;
  // The live progress line of long STAT_NON_LINE runs: on a terminal only, never in the .mess.
  if (options.echo && isatty(STDOUT_FILENO) != 0) {
    setProgressTerminal(&std::cout);
  }
  options.commandLine = args.commandLine;
  options.maxOperations = args.maxOperations;
  options.maxMemoryBytes = args.maxMemoryMiB << 20;
  options.supervised = true;

  std::filesystem::path target(args.target);
  try {
    JobResult job;
    if (target.extension() == ".export") {
      if (!args.units.empty()) {
        std::cerr << "stella: --unit goes with a .comm file; a .export declares its units itself\n";
        return exitUsage;
      }
      Export study = Export::read(target);
      if (const int processes = mpiProcessesOf(study); processes > 1 && !mpi::underLauncher()) {
        return relaunch(study, processes, args);
      }
      if (args.confine) {
        confineExport(study, options.outputDirectory);
      }
      job = runExport(study, options);
    } else {
      std::map<int, std::filesystem::path> units;
      for (const auto& u : args.units) {
        int unit = 0;
        std::string path;
        if (!parseUnit(u, unit, path)) {
          std::cerr << "stella: --unit expects UNIT=PATH with a unit from 1 to 99 other than 6 and 15, got '"
                    << u << "'\n       example: --unit 20=mesh.med\n";
          return exitUsage;
        }
        units[unit] = path;
      }
      if (args.confine) {
        confineCommandFile(target, units, options.outputDirectory);
      }
      job = runCommandFile(target, units, options);
    }
    if (mpi::rank() == 0) {
      printOutcome(job);
    }
    const int code = exitCode(job.diagnostic);
    // A message file that could not be copied back after an OK run is still an error.
    return code == 0 && !job.copyFailures.empty() ? exitCode(JobDiagnostic::Error) : code;
  } catch (const UserError& e) {
    for (const auto& d : e.diagnostics()) {
      std::cerr << formatDiagnostic(d);
    }
    return exitInput;
  } catch (const std::exception& e) {
    // Before the message file exists (the work directory cannot be made...): standard error.
    const Diagnostic d = diagnosticOf(e, msg::text("DURING.prepare"));
    std::cerr << formatDiagnostic(d);
    return exitCode(d.kind == FailureKind::Abort ? JobDiagnostic::AbnormalAbort : JobDiagnostic::Error);
  }
}

} // namespace stella::cli
