#pragma once
// The runs of a sweep: the grid of series x [vary] values, and what each run's files become
// (the template command files with the parameters' values, the export pointing at them).

#include "SweepSpec.hpp"

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace stella::sweep {

struct RunPoint {
  int index = 0;
  std::string series;
  std::vector<Setting> settings; // one per parameter column, in column order ("" where not set)
  std::string label;             // "GCP H=0.5": the series and the values of [vary]
};

// The parameter columns: the [vary] names, then the names the series set, in first-seen order.
std::vector<std::string> parameterColumns(const SweepSpec& spec);

// Every series crossed with every combination of the [vary] values (the first parameter varies
// slowest). Without [series], one series named by the series parameter's value, or "study".
std::vector<RunPoint> expandGrid(const SweepSpec& spec);

// Replaces the value of each top-level one-line assignment `NAME = ...` of a command file (a line
// starting with NAME) before its DEBUT() (or POURSUITE()) line by the setting's value (after it, a
// name is a concept's, `MESH = LIRE_MAILLAGE(...)`); the names replaced are added to `used`.
std::string substituteAssignments(const std::string& text, const std::vector<Setting>& settings,
                                  std::set<std::string>& used);

// Replaces {NAME} by the setting's value and {mesh} by `meshPath` in the mesh command. Throws
// SweepError for a {NAME} that is no parameter.
std::string substituteBraces(const std::string& command, const std::vector<Setting>& settings,
                             const std::string& meshPath, std::set<std::string>& used);

} // namespace stella::sweep
