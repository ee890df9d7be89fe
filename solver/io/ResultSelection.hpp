#pragma once
// What the text and VTU result writers write (see ResultWriters.hpp): the selected steps, fields
// and components of a result, and opening an output file with a located error.

#include "solver/io/MeshFileError.hpp"
#include "solver/io/ResultWriters.hpp"

#include <algorithm>
#include <fstream>

namespace stella::detail {

inline std::vector<const ResultStep*> selectedSteps(const Result* result, const ResultOutput& out) {
  std::vector<const ResultStep*> s;
  if (result != nullptr) {
    for (const auto& step : result->steps) {
      if (out.steps.empty() ||
          std::find(out.steps.begin(), out.steps.end(), step.number) != out.steps.end()) {
        s.push_back(&step);
      }
    }
  }
  return s;
}

inline std::vector<std::string> selectedFields(const Result* result, const ResultOutput& out) {
  return result == nullptr ? std::vector<std::string>{}
                           : (out.fields.empty() ? result->fieldNames() : out.fields);
}

// The indices of the components of `f` that NOM_CMP keeps.
inline std::vector<std::size_t> keptComponents(const Field& f, const ResultOutput& out) {
  std::vector<std::size_t> k;
  for (std::size_t c = 0; c < f.componentCount(); ++c) {
    if (out.components.empty() ||
        std::find(out.components.begin(), out.components.end(), f.components()[c]) != out.components.end()) {
      k.push_back(c);
    }
  }
  return k;
}

inline std::ofstream openOutput(const std::filesystem::path& file, std::ios::openmode mode = std::ios::out) {
  std::ofstream out(file, mode);
  if (!out) {
    throwFileError("MESHFILE_7.8", file, {});
  }
  return out;
}

} // namespace stella::detail
