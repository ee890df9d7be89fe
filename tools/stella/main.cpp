// stella: runs code_aster-style command files for structural mechanics with contact.
// This file only declares the command line; each subcommand lives in its own file.

#include "Commands.hpp"
#include "interpreter/Suggest.hpp"
#include "solver/parallel/Mpi.hpp"

#include <cstdio>
#include <cstdlib>
#include <exception>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

namespace {

const char* const description = R"(stella runs code_aster-style command files (.comm) for structural mechanics
with contact and friction, in batch through .export run files.

Examples:
  stella run study.export                     batch run: results where the export says
  stella run study.comm --unit 20=mesh.med    quick run: results beside study.comm
  stella check study.comm                     validate every command without running
  stella check study.comm --unit 20=mesh.med  ... and check the groups against the mesh
  stella check --syntax study.comm            parse only
  stella catalog DEFI_CONTACT                 the keyword tree of a command
  stella catalog --list                       every command stella knows
  stella convert mesh.msh mesh.med            mesh conversion (Gmsh, ASTER, MED)
  stella sweep study.sweep -j 2               error against time over a grid (doc/sweep.md)
  stella sweep study.export --vary N=4,8,16   the same without a sweep file

Exit codes of `stella run` (the job diagnostic at the end of the message file):
  0  OK or <A>_ALARM          1  NOOK_TEST_RESU or NO_TEST_RESU
  2  <F>_SYNTAX_ERROR         3  <F>_ERROR
  4  <S>_NO_CONVERGENCE       5  <F>_ABNORMAL_ABORT
  6  <S>_INTERRUPTED (signal) 7  <S>_CPU_LIMIT (P time_limit)
  64 bad command line         65 unreadable or malformed .export / input file
`stella check` exits 0 when the file is valid, 2 when it is not.)";

std::string joinArguments(int argc, char** argv) {
  std::string out;
  for (int i = 0; i < argc; ++i) {
    out += (i ? " " : "") + std::string(argv[i]);
  }
  return out;
}

// The subcommand names, for "did you mean" when the first argument is none of them.
const std::vector<std::string> subcommands{"run", "check", "fmt", "catalog", "convert", "sweep"};

// `stella chek ...`: CLI11 would only say that "chek" was not expected; name the nearest one.
bool refusedUnknownSubcommand(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') {
    return false;
  }
  const std::string word = argv[1];
  if (std::find(subcommands.begin(), subcommands.end(), word) != subcommands.end()) {
    return false;
  }
  std::cerr << "stella: unknown subcommand '" << word << "'\n";
  const std::string near = stella::nearestName(word, subcommands);
  if (!near.empty()) {
    std::cerr << "       did you mean `stella " << near << "`?\n";
  }
  std::cerr << "       `stella --help` lists the subcommands\n";
  return true;
}

} // namespace

int main(int argc, char** argv) {
  CLI::App app{description, "stella"};
  app.set_version_flag("--version",
                       std::string("stella ") + STELLA_VERSION + " (commit " + STELLA_GIT_COMMIT + ")");
  app.require_subcommand(1);

  stella::cli::RunArguments runArgs;
  runArgs.commandLine = joinArguments(argc, argv);
  runArgs.arguments.assign(argv, argv + argc);
  auto* run = app.add_subcommand("run", "Run a study: a .export file, or a .comm file with --unit");
  run->add_option("study", runArgs.target, "the .export or .comm file")->required()->check(CLI::ExistingFile);
  run->add_option("--unit", runArgs.units, "with a .comm: a data unit, e.g. --unit 20=mesh.med");
  run->add_option("--work-dir", runArgs.workDirectory, "work directory (default: a new temporary one)");
  run->add_option("--output-dir", runArgs.outputDirectory,
                  "base directory of relative result paths (default: the export's or the .comm's folder)");
  run->add_flag("--reference-only", runArgs.referenceOnly,
                "count only reference lines of TEST_RESU; VALE_CALC lines are information");
  run->add_flag("--keep-work", runArgs.keepWork, "keep the work directory after a successful run");
  run->add_flag("-q,--quiet", runArgs.quiet, "do not copy the message file to standard output");
  run->add_flag("--confine", runArgs.confine,
                "refuse any data or result path that resolves outside the study's folder");
  const char* operationsHelp = "evaluation budget of the command files: operations (default 1000000000)";
  const char* memoryHelp = "evaluation budget: MiB the command files' values may hold (default 2048, at "
                           "most half the RAM)";
  run->add_option("--max-operations", runArgs.maxOperations, operationsHelp)->check(CLI::PositiveNumber);
  run->add_option("--max-memory", runArgs.maxMemoryMiB, memoryHelp)->check(CLI::PositiveNumber);

  stella::cli::CheckArguments checkArgs;
  auto* check = app.add_subcommand("check", "Validate a command file without running it");
  check->add_option("file", checkArgs.file, "the .comm file, or the .export (its units, its command files)")
      ->required()
      ->check(CLI::ExistingFile);
  check->add_flag("--syntax", checkArgs.syntaxOnly, "parse only");
  check->add_flag("--dump-tokens", checkArgs.dumpTokens, "print the tokens");
  check->add_flag("--dump-ast", checkArgs.dumpAst, "print the syntax tree");
  check->add_option("--unit", checkArgs.units,
                    "N: a result unit the study's export declares (besides 6, 8, 80, 81); N=FILE: a data "
                    "unit (the mesh), read so its groups are checked");
  check->add_option("--max-operations", checkArgs.maxOperations, operationsHelp)->check(CLI::PositiveNumber);
  check->add_option("--max-memory", checkArgs.maxMemoryMiB, memoryHelp)->check(CLI::PositiveNumber);

  std::string fmtFile;
  bool fmtInPlace = false;
  auto* fmtCmd = app.add_subcommand("fmt", "Pretty-print a command file");
  fmtCmd->add_option("file", fmtFile, "the .comm file")->required()->check(CLI::ExistingFile);
  fmtCmd->add_flag("-i,--in-place", fmtInPlace, "rewrite the file");

  stella::cli::CatalogArguments catalogArgs;
  auto* catalog = app.add_subcommand("catalog", "Show the keyword catalogue");
  catalog->add_option("command", catalogArgs.command, "a command name, e.g. DEFI_CONTACT");
  catalog->add_flag("--json", catalogArgs.json, "the whole catalogue as JSON");
  catalog->add_flag("--list", catalogArgs.list, "the command names, and whether each is implemented");

  std::string convertIn;
  std::string convertOut;
  auto* convert = app.add_subcommand("convert", "Convert a mesh between formats (.msh, .mail, .med)");
  convert->add_option("input", convertIn, "the mesh to read (.msh, .mail, .med)")
      ->required()
      ->check(CLI::ExistingFile);
  convert->add_option("output", convertOut, "the mesh to write (.med, .mail, .msh)")->required();

  stella::cli::SweepArguments sweepArgs;
  sweepArgs.commandLine = runArgs.commandLine;
  auto* sweep = app.add_subcommand("sweep", "Run a study over a grid of parameters: error against time "
                                            "(doc/sweep.md)");
  sweep->add_option("sweep", sweepArgs.target, "the sweep file, or a .export with --vary")
      ->check(CLI::ExistingFile);
  sweep->add_option("--vary", sweepArgs.vary, "NAME=v1,v2,...: a parameter and its values (repeatable)")
      ->allow_extra_args(false);
  sweep->add_option("-j,--jobs", sweepArgs.jobs, "runs at the same time (default 1)")
      ->check(CLI::Range(1, 256));
  sweep->add_option("--repeats", sweepArgs.repeats, "runs of each point, the median shown (default 3)")
      ->check(CLI::PositiveNumber);
  sweep->add_option("--output-dir", sweepArgs.outputDir, "where the tables go (default: <sweep>_sweep/)");
  sweep->add_option("--error", sweepArgs.error, "the reference test (LEGENDE) the figure shows");
  sweep->add_flag("--keep-runs", sweepArgs.keepRuns, "keep the files of the runs that ended well");
  sweep->add_flag("--no-plot", sweepArgs.noPlot, "write the CSV and Markdown tables only");
  sweep->add_option("--report", sweepArgs.report, "draw the figure and tables again from DIR/sweep.csv")
      ->check(CLI::ExistingDirectory);

  // The last resort of the single error path: an exception that escaped every handler is a bug
  // in stella, reported as <F>_ABNORMAL_ABORT's exit code, never as a crash (134).
  std::set_terminate([] {
    std::fputs("stella: <F> <INTERNAL_3> an error escaped every handler of the run: this is a bug in "
               "stella, please report it with the command file\n",
               stderr);
    std::_Exit(5);
  });
  if (refusedUnknownSubcommand(argc, argv)) {
    return stella::cli::exitUsage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : stella::cli::exitUsage;
  }

  if (run->parsed()) {
    const int code = stella::cli::run(runArgs);
    stella::mpi::finalise(); // when the run initialised MPI
    return code;
  }
  if (check->parsed()) {
    return stella::cli::check(checkArgs);
  }
  if (fmtCmd->parsed()) {
    return stella::cli::format(fmtFile, fmtInPlace);
  }
  if (catalog->parsed()) {
    return stella::cli::catalog(catalogArgs);
  }
  if (convert->parsed()) {
    return stella::cli::convert(convertIn, convertOut);
  }
  if (sweep->parsed()) {
    if (sweepArgs.target.empty() == sweepArgs.report.empty()) {
      std::cerr << "stella sweep: give a sweep file (or a .export with --vary), or --report DIR\n";
      return stella::cli::exitUsage;
    }
    return stella::cli::sweep(sweepArgs);
  }
  return stella::cli::exitUsage;
}
