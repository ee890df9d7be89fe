#pragma once
// One run of one or more command files: the units (files) the export declares, the message
// and result files, the concepts made so far, the diagnostics counts, timings and test counts.
// Implements CommandHandler: each command call is validated against the catalogue, echoed
// with every keyword to the message file under its file:line, executed by its operator, and
// timed (DESIGN §2).

#include "interpreter/CommandHandler.hpp"
#include "interpreter/Diagnostics.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/post/TestReportSink.hpp"

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace stella {

struct OperatorCall;

class Catalog;
class KeywordTree;

struct SessionOptions {
  // false for `stella check`: validate only, except the operators that only compute values of the
  // language (FIN, FORMULE, DEFI_FONCTION, DEFI_CONSTANTE, DEFI_LIST_REEL: see runsWhenChecking in
  // Session.cpp), so that a formula's syntax is checked and F(x) or a list can be used later in the
  // file.
  bool executeOperators = true;
  bool referenceOnly = false; // --reference-only: VALE_CALC lines are information
  std::filesystem::path workDirectory = ".";
  // Where the steps of a result whose command failed are copied back, as
  // <keptResultsDirectory>/<keptResultsStem>.<RESULT>.incomplete.rmed (empty: not written).
  std::filesystem::path keptResultsDirectory;
  std::string keptResultsStem;
  // P ncpus of the export: the threads a command may use (today the contact pairing's).
  int cpus = 1;
};

// A file the run writes on its own (the steps of a failed command): in the work directory, and
// where it is copied back.
struct KeptFile {
  std::filesystem::path work;
  std::filesystem::path destination;
};

// Counts that decide the job diagnostic.
struct SessionCounts {
  int alarms = 0;
  int testsOk = 0;
  int testsNook = 0;
  FailureKind failure = FailureKind::None; // the first fatal failure, if any
};

struct CommandTiming {
  std::string command;
  std::string location; // file:line
  double seconds = 0.0;
};

// An alarm held until the end of the study, because a later command may explain it (MESHCHECK_1:
// coincident nodes that a DEFI_CONTACT joins). `diagnostics` is asked once, at FIN or when the run
// stops.
class DeferredReport {
public:
  virtual ~DeferredReport() = default;
  virtual std::vector<Diagnostic> diagnostics() const = 0;
};

// A diagnostic in the code_aster-style frame of the message file (" ! <F> <ID>" ...).
std::string framedDiagnostic(const Diagnostic& d);

class Session : public CommandHandler, public DiagnosticSink, public TestReportSink {
public:
  Session(const Catalog& catalog, std::ostream& message, std::ostream& result, SessionOptions options);
  ~Session() override;

  // Declared units: unit number -> path of the file (in the work directory). Unit 6 is the
  // message file, unit 8 the result file, unit 80 the MED result by convention.
  void declareUnit(int unit, std::filesystem::path path);
  // The user's own file behind a unit (e.g. mesh.med for fort.20): messages name it rather
  // than the copy in the work directory.
  void declareUnitOrigin(int unit, std::filesystem::path userFile);
  // The path for a unit; throws UserError (UNIT_1) naming the unit and the declared ones when
  // the unit is unknown and `mustExist`.
  std::filesystem::path unitPath(int unit, const SourceLocation& at, bool forReading) const;
  const std::map<int, std::filesystem::path>& units() const { return units_; }
  // The units whose files come back from the run (the export's R lines, the quick run's 6, 8,
  // 80, 81). Once any is declared, a command writing to another unit is refused (UNIT_2): its
  // file would be lost (OutputUnits.cpp).
  void declareResultUnit(int unit);
  // IMPR_RESU / IMPR_TABLE: the unit they write is declared, and holds one format per run
  // (UNIT_3); checked before the command runs, so `stella check` reports it too.
  void checkOutputUnit(const std::string& command, const KeywordTree& keywords, const SourceLocation& call);
  // Units a command opened (the export's data files the study never opened get an alarm only
  // when they are also missing).
  const std::vector<int>& openedUnits() const { return opened_; }

  std::ostream& message() { return message_; }
  std::ostream& result() { return result_; }
  const SessionOptions& options() const { return options_; }
  const Catalog& catalog() const { return catalog_; }

  // DiagnosticSink: writes to the message file in code_aster's framed style and counts.
  void report(const Diagnostic& d) override;
  // Deferred alarms: held by `defer`, found again by the commands that may explain them, reported
  // by `reportDeferred` (FIN, and the batch job when the run stops before FIN; only once).
  void defer(std::shared_ptr<DeferredReport> r) { deferred_.push_back(std::move(r)); }
  const std::vector<std::shared_ptr<DeferredReport>>& deferred() const { return deferred_; }
  void reportDeferred();
  // TestReportSink: TEST_RESU / TEST_TABLE write to the result and message files and record each
  // OK/NOOK line here.
  bool referenceOnlyTests() const override { return options_.referenceOnly; }
  void writeTestLines(const std::string& text) override;
  void recordTest(bool ok) override;
  void noteFailure(FailureKind kind);

  const SessionCounts& counts() const { return counts_; }
  const std::vector<CommandTiming>& timings() const { return timings_; }

  // `stella check` (executeOperators false): each command's errors go to `sink` and the file goes
  // on with a placeholder concept, so one pass reports every command's errors; the operators that
  // only define data (meshes read from a declared unit, models, materials, loads...) run when
  // their inputs are real, so their checks (groups in the mesh...) are made (CheckMode.cpp).
  void collectErrorsIn(DiagnosticSink& sink) { checkSink_ = &sink; }

  // CommandHandler
  Value callCommand(const std::string& command, const CallArguments& args,
                    const std::string& target) override;
  Value conceptAttribute(const std::shared_ptr<Concept>& object, const std::string& name,
                         const SourceLocation& at) override;
  bool finished() const override { return finished_; }
  void markFinished() { finished_ = true; }

  // Every concept made so far, by name (the last one of a name wins).
  const ConceptStore& concepts() const { return concepts_; }

  // Called by operators that keep results after a failure, so the message file can say where
  // they are.
  void noteKeptResult(const std::string& description) { keptResults_.push_back(description); }
  const std::vector<std::string>& keptResults() const { return keptResults_; }
  const std::vector<KeptFile>& keptFiles() const { return keptFiles_; }

  // The concept an operator is making (OperatorCall::makeConcept): when the operator fails,
  // the steps it already computed are written to a MED file (keepPartialResult).
  void noteConceptInProgress(std::shared_ptr<Concept> c) { inProgress_ = std::move(c); }

private:
  const Catalog& catalog_;
  std::ostream& message_;
  std::ostream& result_;
  SessionOptions options_;
  std::map<int, std::filesystem::path> units_;
  std::map<int, std::filesystem::path> unitOrigins_;
  std::vector<int> resultUnits_;
  std::map<int, std::pair<std::string, SourceLocation>> unitFormats_; // unit -> format, first writer
  UserError withUserPaths(const UserError& e) const;
  UserError keepPartialResult(const UserError& e);
  Value runOperator(Value (*op)(OperatorCall&), OperatorCall& opCall);
  mutable std::vector<int> opened_;
  SessionCounts counts_;
  std::vector<CommandTiming> timings_;
  ConceptStore concepts_;
  std::vector<std::string> keptResults_;
  std::vector<KeptFile> keptFiles_;
  std::shared_ptr<Concept> inProgress_;
  std::vector<std::shared_ptr<DeferredReport>> deferred_;
  bool finished_ = false;
  int commandCount_ = 0;
  DiagnosticSink* checkSink_ = nullptr;
  Value callCommandOnce(const std::string& command, const CallArguments& args, const std::string& target);
  Value checkPlaceholder(const std::string& command, const CallArguments& args, const std::string& target);
  bool runsInCheck(const std::string& command, const KeywordTree& keywords) const;
};

} // namespace stella
