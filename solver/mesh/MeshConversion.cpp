// CREA_MAILLAGE operations (see MeshConversion.hpp).

#include "solver/mesh/MeshConversion.hpp"

#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <map>
#include <optional>

namespace stella {

namespace {

std::optional<CellType> targetOf(CellConversion k, CellType t) {
  switch (k) {
  case CellConversion::LineToQuad:
    return t != CellType::POI1 && t == linearType(t) ? std::optional<CellType>(quadraticType(t))
                                                     : std::nullopt;
  case CellConversion::QuadToLine:
    return t != linearType(t) ? std::optional<CellType>(linearType(t)) : std::nullopt;
  case CellConversion::Hexa20To27:
    return t == CellType::HEXA20  ? std::optional<CellType>(CellType::HEXA27)
           : t == CellType::QUAD8 ? std::optional<CellType>(CellType::QUAD9)
                                  : std::nullopt;
  case CellConversion::Penta15To18:
    return t == CellType::PENTA15 ? std::optional<CellType>(CellType::PENTA18)
           : t == CellType::QUAD8 ? std::optional<CellType>(CellType::QUAD9)
                                  : std::nullopt;
  case CellConversion::Quad8To9:
    return t == CellType::QUAD8 ? std::optional<CellType>(CellType::QUAD9) : std::nullopt;
  case CellConversion::Tria6To7:
    return t == CellType::TRIA6 ? std::optional<CellType>(CellType::TRIA7) : std::nullopt;
  case CellConversion::Seg3To4:
    return t == CellType::SEG3 ? std::optional<CellType>(CellType::SEG4) : std::nullopt;
  }
  return std::nullopt;
}

// Shared new nodes, keyed by the sorted old nodes that define them (plus a tag).
class NodeMaker {
public:
  explicit NodeMaker(Mesh& m) : mesh_(m) {}
  NodeId get(std::vector<NodeId> key, int tag, const Point3& x) {
    std::sort(key.begin(), key.end());
    key.push_back(tag);
    const auto it = made_.find(key);
    if (it != made_.end()) {
      return it->second;
    }
    const NodeId n = mesh_.addNode(x);
    made_.emplace(std::move(key), n);
    return n;
  }

private:
  Mesh& mesh_;
  std::map<std::vector<NodeId>, NodeId> made_;
};

Point3 combination(const Mesh& m, const std::vector<std::pair<NodeId, double>>& terms) {
  Point3 x{0, 0, 0};
  for (const auto& [n, w] : terms) {
    x = x + w * m.point(n);
  }
  return x;
}

// Centre of a face given by its old node ids: the face's own interpolation at its centre.
Point3 faceCentre(const Mesh& m, const std::vector<NodeId>& faceNodes, int vertices) {
  std::vector<std::pair<NodeId, double>> t;
  const bool quadratic = static_cast<int>(faceNodes.size()) > vertices;
  for (int i = 0; i < static_cast<int>(faceNodes.size()) && i < 2 * vertices; ++i) {
    double w = 1.0 / vertices;
    if (quadratic) {
      w = vertices == 4 ? (i < 4 ? -0.25 : 0.5) : (i < 3 ? -1.0 / 9.0 : 4.0 / 9.0);
    }
    t.emplace_back(faceNodes[static_cast<std::size_t>(i)], w);
  }
  return combination(m, t);
}

std::vector<NodeId> convertOne(Mesh& out, NodeMaker& maker, CellType from, CellType to,
                               std::span<const NodeId> nodes) {
  std::vector<NodeId> result;
  const int nv = vertexCount(from);
  if (to == linearType(to) || to == linearType(from)) { // QUAD_LINE
    result.assign(nodes.begin(), nodes.begin() + nv);
    return result;
  }
  if (to == CellType::SEG4) {
    const Point3 a = combination(out, {{nodes[0], 2.0 / 9.0}, {nodes[1], -1.0 / 9.0}, {nodes[2], 8.0 / 9.0}});
    const Point3 b = combination(out, {{nodes[0], -1.0 / 9.0}, {nodes[1], 2.0 / 9.0}, {nodes[2], 8.0 / 9.0}});
    return {nodes[0], nodes[1], maker.get({nodes[0], nodes[1]}, 1, a), maker.get({nodes[0], nodes[1]}, 2, b)};
  }
  result.assign(nodes.begin(), nodes.end());
  result.resize(static_cast<std::size_t>(nodeCount(to)), -1);
  for (const auto& e : cellEdges(to)) {
    if (e.mid >= 0 && result[static_cast<std::size_t>(e.mid)] < 0) {
      const NodeId a = nodes[static_cast<std::size_t>(e.a)];
      const NodeId b = nodes[static_cast<std::size_t>(e.b)];
      result[static_cast<std::size_t>(e.mid)] = maker.get({a, b}, 0, 0.5 * (out.point(a) + out.point(b)));
    }
  }
  for (const auto& f : cellFaces(to)) {
    const int fv = vertexCount(f.type);
    if (dimension(to) == 3 && static_cast<int>(f.nodes.size()) == 2 * fv + 1 &&
        result[static_cast<std::size_t>(f.nodes.back())] < 0) {
      std::vector<NodeId> fn;
      for (std::size_t i = 0; i + 1 < f.nodes.size(); ++i) {
        fn.push_back(result[static_cast<std::size_t>(f.nodes[i])]);
      }
      std::vector<NodeId> key(fn.begin(), fn.begin() + fv);
      result[static_cast<std::size_t>(f.nodes.back())] = maker.get(key, 0, faceCentre(out, fn, fv));
    }
  }
  if (result.back() < 0) { // cell centre: QUAD9, TRIA7, HEXA27
    std::vector<std::pair<NodeId, double>> t;
    if (to == CellType::HEXA27) {
      for (int i = 0; i < 20; ++i) {
        t.emplace_back(result[static_cast<std::size_t>(i)], i < 8 ? -0.25 : 0.25);
      }
    } else {
      // Shared with the volume cell whose face this is (HEXA20_27 converts both).
      const std::vector<NodeId> fn(result.begin(), result.end() - 1);
      result.back() = maker.get(std::vector<NodeId>(fn.begin(), fn.begin() + nv), 0, faceCentre(out, fn, nv));
      return result;
    }
    result.back() = out.addNode(combination(out, t));
  }
  return result;
}

Mesh copyNodes(const Mesh& mesh) {
  Mesh out;
  out.setDimension(mesh.dimension());
  out.setName(mesh.name());
  out.reserveNodes(mesh.nodeCount());
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    if (mesh.nodeNames().isDefault()) {
      out.addNode(mesh.point(n));
    } else {
      out.addNode(mesh.point(n), mesh.nodeName(n));
    }
  }
  return out;
}

CellId addNamedCell(Mesh& out, const Mesh& src, CellId c, CellType t, std::span<const NodeId> nodes) {
  return src.cellNames().isDefault() ? out.addCell(t, nodes) : out.addCell(t, nodes, src.cellName(c));
}

// Removes the nodes no cell uses (node groups lose them too).
Mesh compactNodes(const Mesh& m) {
  std::vector<bool> used(static_cast<std::size_t>(m.nodeCount()), false);
  for (CellId c = 0; c < m.cellCount(); ++c) {
    for (const NodeId n : m.cellNodes(c)) {
      used[static_cast<std::size_t>(n)] = true;
    }
  }
  std::vector<NodeId> renum(used.size(), -1);
  Mesh out;
  out.setDimension(m.dimension());
  out.setName(m.name());
  for (NodeId n = 0; n < m.nodeCount(); ++n) {
    if (used[static_cast<std::size_t>(n)]) {
      renum[static_cast<std::size_t>(n)] =
          m.nodeNames().isDefault() ? out.addNode(m.point(n)) : out.addNode(m.point(n), m.nodeName(n));
    }
  }
  for (CellId c = 0; c < m.cellCount(); ++c) {
    std::vector<NodeId> nodes;
    for (const NodeId n : m.cellNodes(c)) {
      nodes.push_back(renum[static_cast<std::size_t>(n)]);
    }
    addNamedCell(out, m, c, m.cellType(c), nodes);
  }
  for (const auto& [g, cells] : m.cellGroups()) {
    out.setCellGroup(g, cells);
  }
  for (const auto& [g, nodes] : m.nodeGroups()) {
    std::vector<NodeId> kept;
    for (const NodeId n : nodes) {
      if (renum[static_cast<std::size_t>(n)] >= 0) {
        kept.push_back(renum[static_cast<std::size_t>(n)]);
      }
    }
    out.setOrderedNodeGroup(g, kept);
  }
  return out;
}

} // namespace

Mesh convertCells(const Mesh& mesh, CellConversion conversion, const std::vector<CellId>& cells) {
  std::vector<bool> selected(static_cast<std::size_t>(mesh.cellCount()), cells.empty());
  for (const CellId c : cells) {
    selected[static_cast<std::size_t>(c)] = true;
  }
  Mesh out = copyNodes(mesh);
  NodeMaker maker(out);
  bool removesNodes = false;
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    const CellType t = mesh.cellType(c);
    const auto target = selected[static_cast<std::size_t>(c)] ? targetOf(conversion, t) : std::nullopt;
    if (!target) {
      addNamedCell(out, mesh, c, t, mesh.cellNodes(c));
      continue;
    }
    removesNodes = removesNodes || nodeCount(*target) < nodeCount(t) || *target == CellType::SEG4;
    const auto nodes = convertOne(out, maker, t, *target, mesh.cellNodes(c));
    addNamedCell(out, mesh, c, *target, nodes);
  }
  for (const auto& [g, ids] : mesh.cellGroups()) {
    out.setCellGroup(g, ids);
  }
  for (const auto& [g, ids] : mesh.nodeGroups()) {
    out.setOrderedNodeGroup(g, ids);
  }
  return removesNodes ? compactNodes(out) : out;
}

Mesh addPointCells(const Mesh& mesh, const std::vector<NodeId>& nodes, const std::string& groupName) {
  Mesh out = copyNodes(mesh);
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    addNamedCell(out, mesh, c, mesh.cellType(c), mesh.cellNodes(c));
  }
  std::vector<CellId> made;
  for (const NodeId n : nodes) {
    const NodeId one[] = {n};
    made.push_back(out.addCell(CellType::POI1, one));
  }
  for (const auto& [g, ids] : mesh.cellGroups()) {
    out.setCellGroup(g, ids);
  }
  for (const auto& [g, ids] : mesh.nodeGroups()) {
    out.setOrderedNodeGroup(g, ids);
  }
  if (!groupName.empty()) {
    out.setCellGroup(groupName, made);
  }
  return out;
}

Mesh restrictMesh(const Mesh& mesh, const std::vector<CellId>& cells,
                  const std::vector<std::string>& keepCellGroups,
                  const std::vector<std::string>& keepNodeGroups) {
  std::vector<CellId> kept = cells;
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  std::vector<CellId> renum(static_cast<std::size_t>(mesh.cellCount()), -1);
  Mesh out = copyNodes(mesh);
  for (const CellId c : kept) {
    renum[static_cast<std::size_t>(c)] = addNamedCell(out, mesh, c, mesh.cellType(c), mesh.cellNodes(c));
  }
  for (const auto& g : keepCellGroups) {
    if (const auto* ids = mesh.cellGroup(g)) {
      std::vector<CellId> mapped;
      for (const CellId c : *ids) {
        if (renum[static_cast<std::size_t>(c)] >= 0) {
          mapped.push_back(renum[static_cast<std::size_t>(c)]);
        }
      }
      out.setCellGroup(g, mapped);
    }
  }
  for (const auto& g : keepNodeGroups) {
    if (const auto* ids = mesh.nodeGroup(g)) {
      out.setOrderedNodeGroup(g, *ids);
    }
  }
  return compactNodes(out);
}

} // namespace stella
