#pragma once
// What a run needs, whether it came from an export or from the command line, and the two halves
// of a supervised run (`stella run` runs the study in a child process so that a crash of the
// process, a library's fault or the system's out-of-memory killer, still ends with the message
// file, the job diagnostic and the result files written before it).

#include "BatchJob.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace stella {

// What a run needs, whether it came from an export or from the command line.
struct JobSpec {
  std::vector<std::filesystem::path> commandFiles;
  struct DataFile {
    int unit;
    std::filesystem::path source;
    std::string origin; // "study.export:5" or "--unit 20=..."
    bool directory;
  };
  std::vector<DataFile> data;
  std::map<int, std::filesystem::path> results; // unit -> destination
  bool isTestcase = false;
  std::vector<std::string> expectedDiagnostics;
  bool saveBase = false;
  bool resultsOptional = false;          // quick runs: say nothing of result units the study did not write
  std::filesystem::path outputDirectory; // where the steps of a failed command are copied back
  std::string stem;                      // of the export or command file: <stem>.<RESULT>.incomplete.rmed
  unsigned timeLimit = 0;                // P time_limit, seconds (0: none)
  double memoryLimit = 0.0;              // P memory_limit, MiB (0: none)
  int cpus = 1;                          // P ncpus
};

// The run in the work directory `work` (made by makeWorkDirectory).
JobResult runInWork(const JobSpec& spec, const RunOptions& options, const std::filesystem::path& work);

// After the process running `spec` in `work` ended on `signal`: the message file gets the
// diagnostic, and the result files the study wrote come back.
JobResult rescueCrashedRun(const JobSpec& spec, const RunOptions& options, const std::filesystem::path& work,
                           int signal);

// Runs runInWork in a child process and waits for it, forwarding the stop signals; rescues the
// run when the child dies on a signal.
JobResult runSupervised(const JobSpec& spec, const RunOptions& options, const std::filesystem::path& work);

// Under mpirun (MpiRun.cpp): the options of this process (no fork, rank 0 alone echoes, a
// --work-dir of its own per rank), and the run of one process of the MPI job in `work`.
RunOptions rankOptions(const RunOptions& options);
JobResult runOnRanks(const JobSpec& spec, const RunOptions& options, const std::filesystem::path& work);

} // namespace stella
