// CREA_MAILLAGE/DECOUPE_LAC on a whole mesh (see LacCutting.hpp).

#include "solver/mesh/LacCutting.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/mesh/CellTopology.hpp"

#include <algorithm>
#include <map>

namespace stella {

namespace {

using Key = std::vector<NodeId>;

Key sortedVertices(std::span<const NodeId> nodes, CellType t) {
  Key k(nodes.begin(), nodes.begin() + vertexCount(t));
  std::sort(k.begin(), k.end());
  return k;
}

std::vector<NodeId> faceNodes(std::span<const NodeId> cellNodes, const CellFace& f) {
  std::vector<NodeId> n;
  for (const int i : f.nodes) {
    n.push_back(cellNodes[static_cast<std::size_t>(i)]);
  }
  return n;
}

struct FaceOwner {
  CellId cell = -1;
  int face = -1;
};

struct Slave {
  CellId cell;
  std::string zone;
};

std::string typeName(CellType t) {
  return std::string(name(t));
}

// The slave cells of the groups, each once (the first group naming it is its zone).
std::vector<Slave> slaveCells(const Mesh& mesh, const std::vector<std::string>& groups, int volumeDim,
                              const SourceLocation& at, LacCuttingReport& report) {
  std::vector<Slave> slaves;
  std::vector<bool> seen(static_cast<std::size_t>(mesh.cellCount()), false);
  for (const auto& g : groups) {
    const auto* ids = mesh.cellGroup(g);
    STELLA_ASSERT(ids != nullptr, "DECOUPE_LAC group " + g);
    report.slaveCellsPerGroup.push_back(static_cast<int>(ids->size()));
    for (const CellId c : *ids) {
      const CellType t = mesh.cellType(c);
      if (dimension(t) != volumeDim - 1) {
        throw UserError(
            msg::make("CREALAC_1",
                      {{"cell_name", mesh.cellName(c)},
                       {"g", g},
                       {"type_name", typeName(t)},
                       {"volume_dim", std::to_string(volumeDim)}},
                      at)
                .withNote(volumeDim == 3 ? msg::text("CREALAC_1.n1") : msg::text("CREALAC_1.n2")));
      }
      if (!seen[static_cast<std::size_t>(c)]) {
        seen[static_cast<std::size_t>(c)] = true;
        slaves.push_back({c, g});
      }
    }
  }
  return slaves;
}

// For each slave cell, the volume cell (and its local face) it is the face of.
std::vector<FaceOwner> faceOwners(const Mesh& mesh, const std::vector<Slave>& slaves, int volumeDim,
                                  const SourceLocation& at) {
  std::map<Key, std::vector<FaceOwner>> owners;
  for (const auto& s : slaves) {
    owners[sortedVertices(mesh.cellNodes(s.cell), mesh.cellType(s.cell))];
  }
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    const CellType t = mesh.cellType(c);
    if (dimension(t) != volumeDim) {
      continue;
    }
    const auto faces = cellFaces(t);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const auto it = owners.find(sortedVertices(faceNodes(mesh.cellNodes(c), faces[f]), faces[f].type));
      if (it != owners.end()) {
        it->second.push_back({c, static_cast<int>(f)});
      }
    }
  }
  std::vector<FaceOwner> out;
  for (const auto& s : slaves) {
    const auto& o = owners[sortedVertices(mesh.cellNodes(s.cell), mesh.cellType(s.cell))];
    const std::string cellName = mesh.cellName(s.cell);
    if (o.empty()) {
      throw UserError(msg::make("CREALAC_2", {{"cell_name", cellName}, {"zone", s.zone}}, at));
    }
    if (o.size() > 1) {
      throw UserError(msg::make("CREALAC_2.2",
                                {{"cell_name", cellName},
                                 {"cell_name_2", mesh.cellName(o[0].cell)},
                                 {"cell_name_3", mesh.cellName(o[1].cell)}},
                                at));
    }
    const CellType ownerType = mesh.cellType(o[0].cell);
    const auto ownerFaces = cellFaces(ownerType);
    const auto& face = ownerFaces[static_cast<std::size_t>(o[0].face)];
    Key a = faceNodes(mesh.cellNodes(o[0].cell), face);
    Key b(mesh.cellNodes(s.cell).begin(), mesh.cellNodes(s.cell).end());
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a != b) {
      throw UserError(msg::make("CREALAC_3",
                                {{"cell_name", cellName},
                                 {"type_name", typeName(mesh.cellType(s.cell))},
                                 {"cell_name_2", mesh.cellName(o[0].cell)},
                                 {"type_name_2", typeName(ownerType)},
                                 {"type_name_3", typeName(face.type)}},
                                at));
    }
    if (lacCutKind(ownerType, mesh.cellType(s.cell)) == LacCutKind::Unsupported) {
      throw UserError(msg::make("CREALAC_4",
                                {{"type_name", typeName(ownerType)},
                                 {"type_name_2", typeName(mesh.cellType(s.cell))},
                                 {"cell_name", cellName}},
                                at));
    }
    out.push_back(o[0]);
  }
  return out;
}

// The piece of `pieces` having the face `key`, and that face's local index.
std::pair<std::size_t, int> pieceWithFace(const std::vector<LacPiece>& pieces, const Key& key) {
  for (std::size_t j = 0; j < pieces.size(); ++j) {
    const auto faces = cellFaces(pieces[j].type);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (sortedVertices(faceNodes(pieces[j].nodes, faces[f]), faces[f].type) == key) {
        return {j, static_cast<int>(f)};
      }
    }
  }
  STELLA_ASSERT(false, "DECOUPE_LAC: a slave face lost by a previous cut");
  return {0, 0};
}

struct NewNodeSource {
  NodeId node;
  CellId source; // the original slave cell the node is on
};

void carryGroups(const Mesh& mesh, Mesh& out, const std::vector<std::vector<CellId>>& outIds,
                 const std::vector<NewNodeSource>& sources) {
  for (const auto& [g, ids] : mesh.cellGroups()) {
    std::vector<CellId> mapped;
    for (const CellId c : ids) {
      const auto& m = outIds[static_cast<std::size_t>(c)];
      mapped.insert(mapped.end(), m.begin(), m.end());
    }
    out.setCellGroup(g, std::move(mapped));
  }
  for (const auto& [g, ids] : mesh.nodeGroups()) {
    std::vector<bool> in(static_cast<std::size_t>(mesh.nodeCount()), false);
    for (const NodeId n : ids) {
      in[static_cast<std::size_t>(n)] = true;
    }
    std::vector<NodeId> nodes = ids;
    for (const auto& s : sources) {
      const auto cn = mesh.cellNodes(s.source);
      if (std::all_of(cn.begin(), cn.end(), [&](NodeId n) { return in[static_cast<std::size_t>(n)]; })) {
        nodes.push_back(s.node);
      }
    }
    out.setOrderedNodeGroup(g, std::move(nodes));
  }
}

// The nodes of `work` (those of `mesh`, then the new ones) named: the old names, then N<k> for
// the k-th node (made unique against the old names, which may be anything).
Mesh namedNodes(const Mesh& mesh, const Mesh& work) {
  Mesh out;
  out.setDimension(mesh.dimension());
  out.setName(mesh.name());
  out.reserveNodes(work.nodeCount());
  if (mesh.nodeNames().isDefault()) {
    for (NodeId n = 0; n < work.nodeCount(); ++n) {
      out.addNode(work.point(n));
    }
    return out;
  }
  for (NodeId n = 0; n < work.nodeCount(); ++n) {
    if (n < mesh.nodeCount()) {
      out.addNode(work.point(n), mesh.nodeName(n));
      continue;
    }
    std::string name = "N" + std::to_string(n + 1);
    for (int k = 1; mesh.findNode(name).has_value(); ++k) {
      name = "N" + std::to_string(n + 1) + "_" + std::to_string(k);
    }
    out.addNode(work.point(n), name);
  }
  return out;
}

} // namespace

Mesh cutMeshForLac(const Mesh& mesh, const std::vector<std::string>& slaveGroups, LacHexaCut mode,
                   const SourceLocation& at, LacCuttingReport* report) {
  LacCuttingReport local;
  LacCuttingReport& r = report != nullptr ? *report : local;
  const int volumeDim = mesh.maxCellDimension();
  const auto slaves = slaveCells(mesh, slaveGroups, volumeDim, at, r);
  const auto owners = faceOwners(mesh, slaves, volumeDim, at);

  // The cuts add their nodes to `work` (default names: adding is O(1)); `out` gets the names.
  Mesh work;
  work.reserveNodes(mesh.nodeCount());
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    work.addNode(mesh.point(n));
  }
  std::map<CellId, std::vector<std::size_t>> slavesOfCell;
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    slavesOfCell[owners[i].cell].push_back(i);
  }
  std::vector<std::vector<LacPiece>> pieces(static_cast<std::size_t>(mesh.cellCount()));
  std::vector<NewNodeSource> sources;
  for (const auto& [cell, list] : slavesOfCell) {
    std::vector<LacPiece> current{
        {mesh.cellType(cell), {mesh.cellNodes(cell).begin(), mesh.cellNodes(cell).end()}}};
    for (const std::size_t i : list) {
      const CellId s = slaves[i].cell;
      if (lacCutKind(mesh.cellType(cell), mesh.cellType(s)) == LacCutKind::Kept) {
        continue;
      }
      const auto [j, f] = pieceWithFace(current, sortedVertices(mesh.cellNodes(s), mesh.cellType(s)));
      LacCut cut = cutCellForLac(work, current[j], f, mesh.cellNodes(s), mode);
      current.erase(current.begin() + static_cast<std::ptrdiff_t>(j));
      current.insert(current.begin() + static_cast<std::ptrdiff_t>(j), cut.cells.begin(), cut.cells.end());
      pieces[static_cast<std::size_t>(s)] = std::move(cut.faces);
      for (const NodeId n : cut.faceNodes) {
        sources.push_back({n, s});
      }
      ++r.cutCells;
    }
    if (current.size() > 1) {
      pieces[static_cast<std::size_t>(cell)] = std::move(current);
    }
  }

  Mesh out = namedNodes(mesh, work);
  std::vector<std::vector<CellId>> outIds(static_cast<std::size_t>(mesh.cellCount()));
  int counter = mesh.cellCount();
  const auto newName = [&] {
    std::string n = "M" + std::to_string(++counter);
    for (int k = 1; mesh.findCell(n).has_value(); ++k) {
      n = "M" + std::to_string(counter) + "_" + std::to_string(k);
    }
    return n;
  };
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    auto& ids = outIds[static_cast<std::size_t>(c)];
    const auto& p = pieces[static_cast<std::size_t>(c)];
    if (p.empty()) {
      ids.push_back(out.addCell(mesh.cellType(c), mesh.cellNodes(c), mesh.cellName(c)));
      continue;
    }
    for (const auto& piece : p) {
      ids.push_back(out.addCell(piece.type, piece.nodes, newName()));
    }
  }
  carryGroups(mesh, out, outIds, sources);
  std::vector<Mesh::LacPatch> patches;
  for (const auto& s : slaves) {
    patches.push_back({s.zone, outIds[static_cast<std::size_t>(s.cell)]});
  }
  out.setLacPatches(std::move(patches));
  return out;
}

} // namespace stella
