// Mesh summaries and statistics (see MeshSummary.hpp).

#include "solver/mesh/MeshSummary.hpp"

#include "solver/mesh/MeshGeometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace stella {

std::string meshSummary(const Mesh& mesh, const std::string& name, bool groups) {
  std::map<CellType, std::size_t> byType;
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    ++byType[mesh.cellType(c)];
  }
  std::string s = fmt::format("   mesh {}: {}D, {} nodes, {} cells ({} cell groups, {} node groups)\n", name,
                              mesh.dimension(), mesh.nodeCount(), mesh.cellCount(), mesh.cellGroups().size(),
                              mesh.nodeGroups().size());
  for (const auto& [t, n] : byType) {
    s += fmt::format("      {:<8} {:>10}\n", stella::name(t), n);
  }
  if (groups) {
    for (const auto& [g, ids] : mesh.cellGroups()) {
      s += fmt::format("      GROUP_MA {:<24} {:>10} cells\n", g, ids.size());
    }
    for (const auto& [g, ids] : mesh.nodeGroups()) {
      s += fmt::format("      GROUP_NO {:<24} {:>10} nodes\n", g, ids.size());
    }
  }
  return s;
}

MeshStatistics meshStatistics(const Mesh& mesh) {
  MeshStatistics s;
  const int top = mesh.maxCellDimension();
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    const CellType t = mesh.cellType(c);
    ++s.cellsByType[t];
    if (dimension(t) != top || top == 0) {
      continue;
    }
    const double a = aspectRatio(mesh, c);
    s.worstAspect = std::max(s.worstAspect, a);
    const double bins[] = {1.5, 2.0, 3.0, 5.0, 10.0};
    std::size_t b = 0;
    while (b < 5 && !(a < bins[b])) {
      ++b;
    }
    ++s.aspectHistogram[b];
    if (isInverted(mesh, c)) {
      ++s.negativeJacobians;
    }
    s.totalMeasure += cellMeasure(mesh, c);
  }
  for (const auto& [g, ids] : mesh.cellGroups()) {
    s.cellGroupSizes[g] = ids.size();
  }
  for (const auto& [g, ids] : mesh.nodeGroups()) {
    s.nodeGroupSizes[g] = ids.size();
  }
  return s;
}

std::string formatStatistics(const MeshStatistics& s, const std::string& name) {
  std::string out = fmt::format("   MACR_INFO_MAIL: mesh {}\n      cells by type:\n", name);
  for (const auto& [t, n] : s.cellsByType) {
    out += fmt::format("         {:<8} {:>10}\n", stella::name(t), n);
  }
  out += "      groups of cells:\n";
  for (const auto& [g, n] : s.cellGroupSizes) {
    out += fmt::format("         {:<24} {:>10}\n", g, n);
  }
  out += "      groups of nodes:\n";
  for (const auto& [g, n] : s.nodeGroupSizes) {
    out += fmt::format("         {:<24} {:>10}\n", g, n);
  }
  static const char* labels[] = {"[1, 1.5)", "[1.5, 2)", "[2, 3)", "[3, 5)", "[5, 10)", ">= 10"};
  out += "      aspect ratio (longest / shortest edge) of the cells of highest dimension:\n";
  for (std::size_t b = 0; b < 6; ++b) {
    out += fmt::format("         {:<10} {:>10}\n", labels[b], s.aspectHistogram[b]);
  }
  out += fmt::format(
      "      worst aspect ratio {:.4g}; cells with a negative jacobian: {}; total measure {:.6g}\n",
      s.worstAspect, s.negativeJacobians, s.totalMeasure);
  return out;
}

} // namespace stella
