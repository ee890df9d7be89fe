#pragma once
// A batch run as code_aster users know it (`stella run STUDY.export`): a clean work directory,
// each data file copied to its unit (fort.<unit>), the command files run in order in one
// session, the result files copied back, and the job diagnostic at the end of the message file.

#include "Export.hpp"
#include "JobDiagnostic.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace stella {

struct RunOptions {
  std::filesystem::path workDirectory;   // empty: a new temporary directory
  std::filesystem::path outputDirectory; // empty: relative result paths are relative to the export
  bool referenceOnly = false;            // VALE_CALC lines are information only
  bool keepWorkDirectory = false;
  bool echo = true;             // copy the message file to standard output as it is written
  std::string commandLine;      // for the message file header
  long long maxOperations = 0;  // evaluation budget of the command files (0: the default)
  long long maxMemoryBytes = 0; // (0: the default)
  // The study runs in a child process; a crash of it still ends with the message file, the job
  // diagnostic and the result files written before (stella run; in-process callers leave it off).
  bool supervised = false;
};

struct JobResult {
  JobDiagnostic diagnostic = JobDiagnostic::AbnormalAbort;
  std::vector<std::filesystem::path> resultFiles; // copied back
  std::filesystem::path workDirectory;            // kept when the run failed
  std::vector<std::string> copyFailures;          // result files that could not be copied back, why
};

JobResult runExport(const Export& study, const RunOptions& options);

// `stella run FILE.comm --unit 20=mesh.med`: outputs beside the command file (FILE.mess,
// FILE.resu, FILE.rmed for unit 80, FILE.pvd for unit 81 with its FILE_<k>.vtu), when written.
JobResult runCommandFile(const std::filesystem::path& commandFile,
                         const std::map<int, std::filesystem::path>& units, const RunOptions& options);

} // namespace stella
