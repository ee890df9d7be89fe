// Skin cells against the volume cells they bound (see SkinOrientation.hpp).

#include "solver/mesh/SkinOrientation.hpp"

#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <map>

namespace stella {

namespace {

int topDimension(const Mesh& mesh) {
  return mesh.dimension() == 2 ? 2 : 3;
}

std::vector<NodeId> sortedVertices(const Mesh& mesh, CellId c) {
  const auto n = mesh.cellNodes(c);
  std::vector<NodeId> key(n.begin(), n.begin() + vertexCount(mesh.cellType(c)));
  std::sort(key.begin(), key.end());
  return key;
}

// Whether the skin cell's vertex order runs along the face's vertex cycle (a rotation of it).
bool runsAlong(const Mesh& mesh, CellId skin, const std::vector<NodeId>& cycle) {
  const auto n = mesh.cellNodes(skin);
  if (cycle.size() == 2) {
    return cycle[0] == n[0];
  }
  const auto pos = static_cast<std::size_t>(std::find(cycle.begin(), cycle.end(), n[0]) - cycle.begin());
  return cycle[(pos + 1) % cycle.size()] == n[1];
}

} // namespace

std::vector<std::vector<BoundedVolume>> boundedVolumes(const Mesh& mesh, const std::vector<CellId>& skin,
                                                       const std::vector<CellId>& volumes) {
  const int top = topDimension(mesh);
  std::map<std::vector<NodeId>, std::vector<std::size_t>> wanted; // vertex set -> skin indices
  for (std::size_t i = 0; i < skin.size(); ++i) {
    if (dimension(mesh.cellType(skin[i])) == top - 1) {
      wanted[sortedVertices(mesh, skin[i])].push_back(i);
    }
  }
  std::vector<std::vector<BoundedVolume>> out(skin.size());
  const auto visit = [&](CellId v) {
    const CellType t = mesh.cellType(v);
    if (dimension(t) != top) {
      return;
    }
    const auto n = mesh.cellNodes(v);
    int winding = 0; // computed once, when a face matches
    for (const auto& f : cellFaces(t)) {
      std::vector<NodeId> cycle;
      for (int i = 0; i < vertexCount(f.type); ++i) {
        cycle.push_back(n[static_cast<std::size_t>(f.nodes[static_cast<std::size_t>(i)])]);
      }
      std::vector<NodeId> key = cycle;
      std::sort(key.begin(), key.end());
      const auto it = wanted.find(key);
      if (it == wanted.end()) {
        continue;
      }
      if (winding == 0) {
        winding = cellWinding(mesh, v);
      }
      for (const std::size_t i : it->second) {
        out[i].push_back({v, runsAlong(mesh, skin[i], cycle) == (winding > 0)});
      }
    }
  };
  if (volumes.empty()) {
    for (CellId v = 0; v < mesh.cellCount(); ++v) {
      visit(v);
    }
  } else {
    for (const CellId v : volumes) {
      visit(v);
    }
  }
  return out;
}

} // namespace stella
