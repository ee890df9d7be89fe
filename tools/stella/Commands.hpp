#pragma once
// The subcommands of the `stella` executable, one function each.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace stella::cli {

struct RunArguments {
  std::string target;             // .export or .comm
  std::vector<std::string> units; // "20=mesh.med"
  std::string workDirectory;
  std::string outputDirectory;
  bool referenceOnly = false;
  bool keepWork = false;
  bool quiet = false;
  bool confine = false; // refuse data and result paths outside the study's folder
  std::string commandLine;
  std::vector<std::string> arguments; // argv, to start again under mpirun (P mpi_nbcpu)
  long long maxOperations = 0;        // the evaluation budget (0: the default, doc/language.md)
  long long maxMemoryMiB = 0;
};
int run(const RunArguments& args);

struct CheckArguments {
  std::string file;
  bool syntaxOnly = false;
  bool dumpTokens = false;
  bool dumpAst = false;
  // "N": a result unit declared besides the quick run's 6, 8, 80, 81; "N=FILE": a data unit.
  std::vector<std::string> units;
  long long maxOperations = 0;
  long long maxMemoryMiB = 0;
};
int check(const CheckArguments& args);

int format(const std::string& file, bool inPlace);

struct CatalogArguments {
  std::string command;
  bool json = false;
  bool list = false;
};
int catalog(const CatalogArguments& args);

int convert(const std::string& in, const std::string& out);

struct SweepArguments {
  std::string target;            // a sweep file, or a .export with --vary
  std::vector<std::string> vary; // "NAME=v1,v2"
  std::string report;            // --report DIR: the figures again from DIR/sweep.csv
  std::string outputDir;
  std::string error; // the reference test the figure shows (its LEGENDE)
  int jobs = 1;
  int repeats = 0; // 0: the sweep file's (default 3)
  bool keepRuns = false;
  bool noPlot = false;
  std::string commandLine;
};
int sweep(const SweepArguments& args);

// Exit codes shared by every subcommand (documented in --help and the README).
inline constexpr int exitUsage = 64;
inline constexpr int exitInput = 65; // a file that cannot be read or is malformed

} // namespace stella::cli
