#pragma once
// Helpers for the tests that run command files and check the files they write: run a .comm
// through the batch runner (outputs beside it: NAME.mess, NAME.resu, NAME.rmed for unit 80,
// NAME.fort.N for other units) and run a Python check with Debian's python3 (meshio, h5py).

#include "solver/job/BatchJob.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

namespace stella::testing {

struct CommRun {
  JobDiagnostic diagnostic;
  std::string message;
};

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline CommRun runComm(const std::filesystem::path& dir, const std::string& name, const std::string& comm,
                       const std::map<int, std::filesystem::path>& units) {
  const auto file = dir / (name + ".comm");
  std::ofstream(file) << comm;
  RunOptions options;
  options.echo = false;
  options.workDirectory = dir / (name + ".work");
  const JobResult r = runCommandFile(file, units, options);
  return {r.diagnostic, readText(dir / (name + ".mess"))};
}

// Writes `script` to DIR/check.py and runs `/usr/bin/python3 check.py ARGS`; its output goes to
// DIR/py.log and is printed when the script fails. Returns the exit status.
inline int runPython(const std::filesystem::path& dir, const std::string& script, const std::string& args) {
  const auto py = dir / "check.py";
  std::ofstream(py) << script;
  const std::string cmd =
      "/usr/bin/python3 " + py.string() + " " + args + " > " + (dir / "py.log").string() + " 2>&1";
  const int rc = std::system(cmd.c_str());
  if (rc != 0) {
    std::cerr << readText(dir / "py.log");
  }
  return rc;
}

} // namespace stella::testing
