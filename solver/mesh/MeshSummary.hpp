#pragma once
// Text summaries of a mesh for the message file (LIRE_MAILLAGE INFO, MACR_INFO_MAIL): counts of
// nodes and of cells by type, groups with their sizes; statistics of cell quality.

#include "solver/mesh/Mesh.hpp"

#include <array>
#include <map>
#include <string>

namespace stella {

// "mesh MAIL: 3D, 125 nodes, 64 cells\n  HEXA8 64 ..." ; with `groups`, every group and its size.
std::string meshSummary(const Mesh& mesh, const std::string& name, bool groups);

// MACR_INFO_MAIL statistics.
struct MeshStatistics {
  std::map<CellType, std::size_t> cellsByType;
  std::map<std::string, std::size_t> cellGroupSizes;
  std::map<std::string, std::size_t> nodeGroupSizes;
  // Aspect ratio (longest / shortest edge) histogram of the cells of the highest dimension:
  // bins [1,1.5) [1.5,2) [2,3) [3,5) [5,10) [10,inf).
  std::array<std::size_t, 6> aspectHistogram{};
  double worstAspect = 1.0;
  std::size_t negativeJacobians = 0; // cells of the highest dimension
  double totalMeasure = 0.0;         // length, area or volume of those cells
};

MeshStatistics meshStatistics(const Mesh& mesh);
std::string formatStatistics(const MeshStatistics& s, const std::string& name);

} // namespace stella
