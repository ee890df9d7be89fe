// A batch run on the processes of `mpirun -n N stella run ...` (issue 21, doc/parallel.md): every
// process runs the whole study in its own work directory; rank 0 alone echoes the message file
// and copies the result files back. The runs agree on the exit code at the end; a process that
// failed alone while the others wait in a MUMPS call ends every process (MPI_Abort) with its
// diagnostic instead of a hang.

#include "JobSpec.hpp"

#include "solver/parallel/Mpi.hpp"

#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace stella {

namespace fs = std::filesystem;

namespace {

// How long a failed process waits at the end for the others before it ends them all: the others
// either failed as well (the same replicated study: they arrive within seconds) or are waiting
// for it inside a collective call.
constexpr double patienceSeconds = 60.0;

std::string fileText(const fs::path& file) {
  std::ifstream in(file);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

} // namespace

RunOptions rankOptions(const RunOptions& options) {
  RunOptions own = options;
  own.supervised = false; // a process of an MPI job must not fork: the study runs in it
  const int rank = mpi::launchedRank();
  if (rank != 0) {
    own.echo = false; // one message file on the terminal: rank 0's
    if (!own.workDirectory.empty()) {
      own.workDirectory += fmt::format(".rank{}", rank);
    }
  }
  return own;
}

JobResult runOnRanks(const JobSpec& spec, const RunOptions& options, const fs::path& work) {
  mpi::initialise();
  const int rank = mpi::rank();
  JobSpec own = spec;
  if (rank != 0) {
    // The same units are declared (the study behaves alike on every process), but the files of
    // the other ranks stay in their work directory, removed after a clean run.
    for (auto& [unit, destination] : own.results) {
      destination = work / "rank-results" / destination.filename();
    }
    own.outputDirectory = work / "rank-results";
    fs::create_directories(own.outputDirectory);
  }
  JobResult job = runInWork(own, options, work);
  const int code = exitCode(job.diagnostic);
  const std::string message =
      fmt::format("stella: MPI rank {} of {} ended with {} while the other processes did not end: every "
                  "process is stopped. Its message file:\n{}\n",
                  rank, mpi::size(), diagnosticWord(job.diagnostic),
                  code != 0 ? fileText(work / "fort.6") : std::string("(kept in its work directory)"));
  const int agreed = mpi::agreeOnExitCode(code, code != 0 ? patienceSeconds : 1.0e9, message);
  if (agreed != code && rank == 0 && code == 0) {
    job.diagnostic = JobDiagnostic::Error; // another rank failed where this one did not
  }
  return job;
}

} // namespace stella
