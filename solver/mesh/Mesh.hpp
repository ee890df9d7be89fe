#pragma once
// The mesh (code_aster's maillage): nodes with three coordinates (z = 0 for 2D meshes, whose
// dimension is stored), cells of any CellType in code_aster's node ordering (CellTopology.hpp),
// node and cell names (N1.../M1... generated on demand, or the file's names), and named groups
// of cells (GROUP_MA) and of nodes (GROUP_NO).
//
// Storage is compact (CSR-like): coordinates in one array, one offsets array and one node array
// for the connectivity, one type byte per cell. Indices are 0-based; names are 1-based.
//
// Building: addNode/addCell (or reserve then add), then groups. Cells and nodes are never
// removed in place: operations that change the topology build a new Mesh.

#include "solver/mesh/CellType.hpp"
#include "solver/mesh/NameTable.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stella {

using NodeId = std::int32_t;
using CellId = std::int32_t;
using Point3 = std::array<double, 3>;

class Mesh {
public:
  Mesh();

  // Space dimension: 2 (all z = 0, code_aster COOR_2D) or 3.
  int dimension() const { return dimension_; }
  void setDimension(int d) { dimension_ = d; }
  // The mesh's name in MED files (empty: the concept name is used by writers).
  const std::string& name() const { return name_; }
  void setName(std::string n) { name_ = std::move(n); }

  // ---- nodes
  NodeId nodeCount() const { return static_cast<NodeId>(coordinates_.size() / 3); }
  void reserveNodes(NodeId n);
  NodeId addNode(const Point3& x);                        // default name
  NodeId addNode(const Point3& x, std::string_view name); // named
  Point3 point(NodeId n) const;
  void setPoint(NodeId n, const Point3& x);
  // x0 y0 z0 x1 y1 z1 ...
  const std::vector<double>& coordinates() const { return coordinates_; }
  std::vector<double>& mutableCoordinates() { return coordinates_; }

  // ---- cells
  CellId cellCount() const { return static_cast<CellId>(types_.size()); }
  void reserveCells(CellId cells, std::size_t connectivity);
  CellId addCell(CellType type, std::span<const NodeId> nodes);                        // default name
  CellId addCell(CellType type, std::span<const NodeId> nodes, std::string_view name); // named
  CellType cellType(CellId c) const { return static_cast<CellType>(types_[static_cast<std::size_t>(c)]); }
  std::span<const NodeId> cellNodes(CellId c) const;
  std::span<NodeId> mutableCellNodes(CellId c);
  // Largest topological dimension among the cells (0 when there are none).
  int maxCellDimension() const;

  // ---- names
  const NameTable& nodeNames() const { return nodeNames_; }
  const NameTable& cellNames() const { return cellNames_; }
  NameTable& mutableNodeNames() { return nodeNames_; }
  NameTable& mutableCellNames() { return cellNames_; }
  std::string nodeName(NodeId n) const { return nodeNames_.name(n); }
  std::string cellName(CellId c) const { return cellNames_.name(c); }
  std::optional<NodeId> findNode(std::string_view name) const { return nodeNames_.find(name); }
  std::optional<CellId> findCell(std::string_view name) const { return cellNames_.find(name); }

  // ---- groups (sorted, duplicate-free index lists, except node groups set ordered by
  // NOEUD_ORDO/SEGM_DROI_ORDO; names in alphabetical order)
  const std::map<std::string, std::vector<CellId>>& cellGroups() const { return cellGroups_; }
  const std::map<std::string, std::vector<NodeId>>& nodeGroups() const { return nodeGroups_; }
  const std::vector<CellId>* cellGroup(const std::string& name) const;
  const std::vector<NodeId>* nodeGroup(const std::string& name) const;
  bool hasCellGroup(const std::string& name) const { return cellGroups_.count(name) != 0; }
  bool hasNodeGroup(const std::string& name) const { return nodeGroups_.count(name) != 0; }
  // Sets (replaces) a group; the list is sorted and made unique.
  void setCellGroup(const std::string& name, std::vector<CellId> cells);
  void setNodeGroup(const std::string& name, std::vector<NodeId> nodes);
  // Sets a node group keeping the given order (duplicates after the first occurrence removed).
  void setOrderedNodeGroup(const std::string& name, std::vector<NodeId> nodes);
  bool removeCellGroup(const std::string& name) { return cellGroups_.erase(name) != 0; }
  bool removeNodeGroup(const std::string& name) { return nodeGroups_.erase(name) != 0; }

  // ---- LAC patches, set by CREA_MAILLAGE/DECOUPE_LAC (empty otherwise; operations that rebuild
  // the mesh drop them): for each slave cell of the original mesh, the slave cells it was cut
  // into and the GROUP_MA_ESCL group (contact zone) it came from.
  struct LacPatch {
    std::string zone;
    std::vector<CellId> cells;
  };
  const std::vector<LacPatch>& lacPatches() const { return lacPatches_; }
  void setLacPatches(std::vector<LacPatch> patches) { lacPatches_ = std::move(patches); }

  // Nodes used by the given cells (sorted, unique).
  std::vector<NodeId> nodesOfCells(std::span<const CellId> cells) const;

  // Bytes held by this mesh (capacity of every array), with or without the groups.
  std::size_t memoryBytes(bool withGroups) const;

private:
  int dimension_ = 3;
  std::string name_;
  std::vector<double> coordinates_;
  std::vector<std::uint64_t> offsets_; // cellCount()+1 entries
  std::vector<NodeId> connectivity_;
  std::vector<std::uint8_t> types_;
  NameTable nodeNames_{'N'};
  NameTable cellNames_{'M'};
  std::map<std::string, std::vector<CellId>> cellGroups_;
  std::map<std::string, std::vector<NodeId>> nodeGroups_;
  std::vector<LacPatch> lacPatches_;
};

} // namespace stella
