#pragma once
// Runs a command file given as text in a Session (unit 20 = a mesh file of the source tree) and
// keeps the session, so tests can look at the concepts it made and at the message file.

#include "catalog/Catalog.hpp"
#include "interpreter/Interpreter.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/session/Session.hpp"

#include <filesystem>
#include <memory>
#include <sstream>
#include <string>

namespace stella::testing {

struct StudyRun {
  std::ostringstream message;
  std::ostringstream resu;
  std::unique_ptr<Session> session;
  RunStatus status = RunStatus::Failed;

  std::shared_ptr<Result> result(const std::string& name) const {
    return session->concepts().findData<Result>(name);
  }
  std::string mess() const { return message.str(); }
  FailureKind failure() const { return session->counts().failure; }
};

// `mesh`: path relative to the source tree (e.g. testcases/plate_plasticity/hexa8.msh).
inline std::unique_ptr<StudyRun> runStudy(const std::string& name, const std::string& comm,
                                          const std::string& mesh) {
  auto run = std::make_unique<StudyRun>();
  const auto work = std::filesystem::temp_directory_path() / ("stella_" + name);
  // A fresh work directory: a unit file left by an earlier run (fort.80 in another MED version)
  // would be appended to.
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  SessionOptions options;
  options.workDirectory = work;
  const Catalog& catalog = Catalog::builtin();
  run->session = std::make_unique<Session>(catalog, run->message, run->resu, options);
  run->session->declareUnit(20, std::filesystem::path(STELLA_SOURCE_DIR) / mesh);
  Interpreter interpreter(*run->session, *run->session);
  for (const auto& command : catalog.commandNames()) {
    interpreter.defineCommand(command);
  }
  run->status = interpreter.run(SourceFile::fromText(name + ".comm", comm));
  return run;
}

} // namespace stella::testing
