#pragma once
// Running a contact study end to end from a test: the mesh written in the ASTER format, the
// command file run by runCommandFile as `stella run` would (without the child process), the job
// diagnostic and the message file returned; a TEST_RESU line against a closed form.

#include "solver/io/MeshIO.hpp"
#include "solver/job/BatchJob.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace stella::contact {

struct StudyRun {
  JobDiagnostic diagnostic = JobDiagnostic::AbnormalAbort;
  std::string message;
};

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// No NOOK and no error (alarms allowed: blocks touching at t = 0 have coincident nodes).
inline bool passed(const StudyRun& r) {
  return r.diagnostic == JobDiagnostic::Ok || r.diagnostic == JobDiagnostic::Alarm;
}

// Runs `comm` on `mesh` in <test temp>/<folder>/<name>; the message file goes to standard error
// when the run did not pass, unless `quiet`.
inline StudyRun runStudyIn(const std::string& folder, const std::string& name, const Mesh& mesh,
                           const std::string& comm, bool quiet = false) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / folder / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeAsterMesh(dir / "mesh.mail", mesh);
  const fs::path file = dir / (name + ".comm");
  std::ofstream(file) << comm;
  RunOptions options;
  options.echo = false;
  options.workDirectory = dir / "work";
  const JobResult r = runCommandFile(file, {{20, dir / "mesh.mail"}}, options);
  StudyRun run{r.diagnostic, readText(dir / (name + ".mess"))};
  if (!quiet && !passed(run)) {
    std::cerr << run.message << "\n";
  }
  return run;
}

// TEST_RESU of the sum (or MIN/MAX) of a nodal component against a closed form.
inline std::string testResu(double inst, const std::string& field, const std::string& cmp,
                            const std::string& group, const std::string& kind, double value,
                            double precision) {
  const bool absolute = value == 0.0;
  return fmt::format(
      "TEST_RESU(RESU=_F(RESULTAT=RESU, INST={}, NOM_CHAM='{}', NOM_CMP='{}', GROUP_NO='{}', "
      "TYPE_TEST='{}', VALE_CALC={:.17g}, TOLE_MACHINE={}, CRITERE='{}', REFERENCE='ANALYTIQUE', "
      "VALE_REFE={:.17g}, PRECISION={}))\n",
      inst, field, cmp, group, kind, value, absolute ? 1.0 : std::max(precision, 1e-6),
      absolute ? "ABSOLU" : "RELATIF", value, precision);
}

} // namespace stella::contact
