#pragma once
// The sweep file of `stella sweep` (doc/sweep.md): a template study, the parameters to vary with
// their values, the series (one line each) and how to make the meshes.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stella::sweep {

// A bad sweep file or option; the message starts with "file:line: " when it has a location.
class SweepError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

using Setting = std::pair<std::string, std::string>; // parameter name, value as written

struct Parameter {
  std::string name;
  std::vector<std::string> values; // each as written: 0.25, 'GCP', {'ALGO_CONT': 'GCP'}
  int line = 0;                    // 0: from the command line (--vary)
};

struct Series {
  std::string name;
  std::vector<Setting> settings;
  int line = 0;
  // An external series (`NAME: ! command`): a shell command run per point instead of stella, with
  // {NAME}, {mesh} and {out} (the file where it writes its results) replaced (doc/sweep.md).
  std::string command;
};

struct SweepSpec {
  std::filesystem::path file;  // the sweep file; empty for `stella sweep study.export --vary ...`
  std::filesystem::path study; // the template .export (absolute)
  std::filesystem::path comm;  // optional: replaces the export's first command file (absolute)
  int repeats = 3;
  double timeout = 600.0;      // seconds per run
  std::string error;           // the reference test whose error the figure shows; empty: the largest
  std::string meshCommand;     // shell command with {NAME} and {mesh}; empty: the export's mesh
  int meshUnit = 0;            // the export's unit the generated mesh replaces
  std::string meshSize;        // the parameter that is the mesh size (x of the second panel)
  std::string seriesParameter; // without [series]: the parameter whose value names the series
  std::string time = "wall";   // the time of the figure and the front: wall or cpu
  std::vector<Parameter> vary;
  std::vector<Series> series;
};

// Parses a sweep file's text; paths are resolved against the file's folder. Throws SweepError.
SweepSpec parseSweepFile(const std::string& text, const std::filesystem::path& file);

// `--vary NAME=v1,v2,...`: adds a parameter or replaces the values of one of the file.
void addVary(SweepSpec& spec, const std::string& option);

// Checks what the file alone cannot: a mesh command needs mesh_unit, mesh_size and the series
// parameter name parameters that exist, repeats >= 1. Throws SweepError.
void validate(const SweepSpec& spec);

// Splits on `separator` outside quotes and brackets, trimming each piece.
std::vector<std::string> splitTopLevel(std::string_view text, char separator);

std::string trim(std::string_view text);

} // namespace stella::sweep
