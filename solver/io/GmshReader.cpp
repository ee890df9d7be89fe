// Gmsh .msh reader: formats 2.2 and 4.1, ASCII (binary files are refused with MESHFILE_5).
// Physical groups become cell groups (named by $PhysicalNames, else "GM<tag>") and node groups
// of the same name; node and cell names are N<tag> and M<tag> from the file's tags.

#include "solver/io/GmshCellTypes.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/TextScanner.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace stella {

namespace {

// Maps the file's node tags to node indices, densely when the tags allow it.
class NodeTags {
public:
  void add(std::int64_t tag, NodeId index, TextScanner& s) {
    if (tag <= 0) {
      s.failContent("node tag " + std::to_string(tag) + " is not positive");
    }
    if (!map_.emplace(tag, index).second) {
      s.failContent("node tag " + std::to_string(tag) + " is defined twice");
    }
  }
  NodeId find(std::int64_t tag, TextScanner& s) const {
    const auto it = map_.find(tag);
    if (it == map_.end()) {
      s.failContent("an element refers to node " + std::to_string(tag) + ", which is not defined");
    }
    return it->second;
  }

private:
  std::unordered_map<std::int64_t, NodeId> map_;
};

struct GmshContent {
  Mesh mesh;
  NodeTags nodes;
  std::map<std::pair<int, int>, std::string> physicalNames; // (dim, tag) -> name
  std::map<std::string, std::vector<CellId>> groups;
  std::map<std::pair<int, int>, std::vector<int>> entityPhysicals; // 4.1: (dim, entity) -> tags
  // Element tag -> cell: a tag repeated with the same nodes is the same cell in another physical
  // group (how overlapping groups are written).
  std::unordered_map<std::int64_t, CellId> cellTags;
  bool allZero = true;
};

std::string groupName(const GmshContent& g, int dim, int tag) {
  const auto it = g.physicalNames.find({dim, tag});
  return it != g.physicalNames.end() ? it->second : "GM" + std::to_string(tag);
}

void skipSection(TextScanner& s, std::string_view name) {
  const std::string end = "$End" + std::string(name.substr(1));
  for (auto t = s.next(); t != end; t = s.next()) {
    if (t.empty()) {
      s.fail("section " + std::string(name) + " has no " + end);
    }
  }
}

void expectEnd(TextScanner& s, const char* end) {
  const auto t = s.expect(end);
  if (t != end) {
    s.fail(std::string("expected ") + end + ", found '" + std::string(t.substr(0, 40)) + "'");
  }
}

void readPhysicalNames(TextScanner& s, GmshContent& g) {
  const auto n = s.count("number of physical names", 6);
  for (std::int64_t i = 0; i < n; ++i) {
    const int dim = static_cast<int>(s.integer("physical dimension"));
    const int tag = static_cast<int>(s.integer("physical tag"));
    const auto name = s.expect("physical name");
    if (dim < 0 || dim > 3) {
      s.failContent("physical dimension " + std::to_string(dim) + " is not 0, 1, 2 or 3");
    }
    g.physicalNames[{dim, tag}] = std::string(name);
  }
  expectEnd(s, "$EndPhysicalNames");
}

Point3 readPoint(TextScanner& s, GmshContent& g) {
  Point3 x{};
  x[0] = s.real("node x coordinate");
  x[1] = s.real("node y coordinate");
  x[2] = s.real("node z coordinate");
  g.allZero = g.allZero && x[2] == 0.0;
  return x;
}

void addNode(TextScanner& s, GmshContent& g, std::int64_t tag, const Point3& x) {
  const NodeId id = g.mesh.addNode(x, "N" + std::to_string(tag));
  g.nodes.add(tag, id, s);
}

CellId addElement(TextScanner& s, GmshContent& g, std::int64_t tag, int gmshType) {
  const auto type = cellTypeFromGmsh(gmshType);
  if (!type) {
    s.failContent("element " + std::to_string(tag) + " has Gmsh type " + std::to_string(gmshType) +
                  ", which has no code_aster cell type");
  }
  const int n = nodeCount(*type);
  NodeId gmshNodes[27];
  for (int i = 0; i < n; ++i) {
    gmshNodes[i] = g.nodes.find(s.integer("element node tag"), s);
  }
  NodeId nodes[27];
  const auto perm = gmshPermutation(*type);
  for (int j = 0; j < n; ++j) {
    nodes[j] = gmshNodes[perm[static_cast<std::size_t>(j)]];
  }
  const std::span<const NodeId> span(nodes, static_cast<std::size_t>(n));
  const auto [it, added] = g.cellTags.emplace(tag, g.mesh.cellCount());
  if (!added) {
    const auto old = g.mesh.cellNodes(it->second);
    if (g.mesh.cellType(it->second) != *type || !std::equal(old.begin(), old.end(), span.begin())) {
      s.failContent("element tag " + std::to_string(tag) + " is defined twice with different nodes");
    }
    return it->second;
  }
  return g.mesh.addCell(*type, span, "M" + std::to_string(tag));
}

// ---- format 2.2

void readNodes22(TextScanner& s, GmshContent& g) {
  const auto n = s.count("number of nodes", 8);
  g.mesh.reserveNodes(static_cast<NodeId>(n));
  for (std::int64_t i = 0; i < n; ++i) {
    const auto tag = s.integer("node tag");
    addNode(s, g, tag, readPoint(s, g));
  }
  expectEnd(s, "$EndNodes");
}

void readElements22(TextScanner& s, GmshContent& g) {
  const auto n = s.count("number of elements", 8);
  for (std::int64_t i = 0; i < n; ++i) {
    const auto tag = s.integer("element tag");
    const int type = static_cast<int>(s.integer("element type"));
    const auto ntags = s.integer("number of element tags");
    if (ntags < 0 || ntags > 100) {
      s.failContent("element " + std::to_string(tag) + " has " + std::to_string(ntags) + " tags");
    }
    int physical = 0;
    for (std::int64_t k = 0; k < ntags; ++k) {
      const auto v = s.integer("element tag value");
      if (k == 0) {
        physical = static_cast<int>(v);
      }
    }
    const auto celltype = cellTypeFromGmsh(type);
    const CellId c = addElement(s, g, tag, type);
    if (physical != 0) {
      g.groups[groupName(g, dimension(*celltype), physical)].push_back(c);
    }
  }
  expectEnd(s, "$EndElements");
}

// ---- format 4.1

void readEntities41(TextScanner& s, GmshContent& g) {
  std::int64_t counts[4];
  for (auto& c : counts) {
    c = s.count("number of entities", 8);
  }
  for (int dim = 0; dim < 4; ++dim) {
    for (std::int64_t i = 0; i < counts[dim]; ++i) {
      const int tag = static_cast<int>(s.integer("entity tag"));
      const int reals = dim == 0 ? 3 : 6;
      for (int k = 0; k < reals; ++k) {
        s.real("entity bounding box");
      }
      const auto nphys = s.count("number of physical tags", 2);
      auto& phys = g.entityPhysicals[{dim, tag}];
      for (std::int64_t k = 0; k < nphys; ++k) {
        phys.push_back(static_cast<int>(s.integer("physical tag")));
      }
      if (dim > 0) {
        const auto nb = s.count("number of bounding entities", 2);
        for (std::int64_t k = 0; k < nb; ++k) {
          s.integer("bounding entity tag");
        }
      }
    }
  }
  expectEnd(s, "$EndEntities");
}

void readNodes41(TextScanner& s, GmshContent& g) {
  const auto blocks = s.count("number of node blocks", 8);
  const auto total = s.count("number of nodes", 8);
  s.integer("minimum node tag");
  s.integer("maximum node tag");
  g.mesh.reserveNodes(static_cast<NodeId>(total));
  std::vector<std::int64_t> tags;
  for (std::int64_t b = 0; b < blocks; ++b) {
    const auto dim = s.integer("entity dimension");
    s.integer("entity tag");
    const auto parametric = s.integer("parametric flag");
    const auto n = s.count("number of nodes in block", 8);
    if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1) {
      s.failContent("bad node block header");
    }
    tags.resize(static_cast<std::size_t>(n));
    for (auto& t : tags) {
      t = s.integer("node tag");
    }
    for (const auto t : tags) {
      addNode(s, g, t, readPoint(s, g));
      for (std::int64_t k = 0; k < parametric * dim; ++k) {
        s.real("node parametric coordinate");
      }
    }
  }
  if (g.mesh.nodeCount() != total) {
    s.failContent("the header announces " + std::to_string(total) + " nodes, the blocks hold " +
                  std::to_string(g.mesh.nodeCount()));
  }
  expectEnd(s, "$EndNodes");
}

void readElements41(TextScanner& s, GmshContent& g) {
  const auto blocks = s.count("number of element blocks", 8);
  const auto total = s.count("number of elements", 4);
  s.integer("minimum element tag");
  s.integer("maximum element tag");
  std::int64_t read = 0;
  for (std::int64_t b = 0; b < blocks; ++b) {
    const int dim = static_cast<int>(s.integer("entity dimension"));
    const int entity = static_cast<int>(s.integer("entity tag"));
    const int type = static_cast<int>(s.integer("element type"));
    const auto n = s.count("number of elements in block", 4);
    const auto it = g.entityPhysicals.find({dim, entity});
    for (std::int64_t i = 0; i < n; ++i) {
      const auto tag = s.integer("element tag");
      const CellId c = addElement(s, g, tag, type);
      if (it != g.entityPhysicals.end()) {
        for (const int p : it->second) {
          g.groups[groupName(g, dim, p)].push_back(c);
        }
      }
    }
    read += n;
  }
  if (read != total) {
    s.failContent("the header announces " + std::to_string(total) + " elements, the blocks hold " +
                  std::to_string(read));
  }
  expectEnd(s, "$EndElements");
}

} // namespace

Mesh readGmshMesh(const std::filesystem::path& file) {
  TextScanner s(file, readWholeFile(file));
  GmshContent g;
  if (s.next() != "$MeshFormat") {
    s.fail("not a Gmsh mesh: the file does not start with $MeshFormat");
  }
  const auto version = s.expect("format version");
  const bool v2 = version.substr(0, 2) == "2.";
  const bool v4 = version == "4.1";
  if (!v2 && !v4) {
    throwFileError("MESHFILE_5", file,
                   "Gmsh format version " + std::string(version.substr(0, 20)) +
                       " is not supported (not implemented yet: only 2.2 and 4.1)",
                   s.line());
  }
  if (s.integer("file type") != 0) {
    throwFileError("MESHFILE_5", file, "binary Gmsh files are not implemented yet (write ASCII: gmsh -bin 0)",
                   s.line());
  }
  s.integer("data size");
  expectEnd(s, "$EndMeshFormat");
  bool sawNodes = false;
  bool sawElements = false;
  for (auto t = s.next(); !t.empty(); t = s.next()) {
    if (t == "$PhysicalNames") {
      readPhysicalNames(s, g);
    } else if (t == "$Entities" && v4) {
      readEntities41(s, g);
    } else if (t == "$Nodes") {
      if (sawNodes) {
        s.fail("a second $Nodes section");
      }
      v4 ? readNodes41(s, g) : readNodes22(s, g);
      sawNodes = true;
    } else if (t == "$Elements") {
      if (!sawNodes) {
        s.fail("$Elements before $Nodes");
      }
      if (sawElements) {
        s.fail("a second $Elements section");
      }
      v4 ? readElements41(s, g) : readElements22(s, g);
      sawElements = true;
    } else if (t.size() > 1 && t[0] == '$' && t.substr(0, 4) != "$End") {
      skipSection(s, t);
    } else {
      s.fail("expected a section ($Nodes, $Elements...), found '" + std::string(t.substr(0, 40)) + "'");
    }
  }
  if (!sawNodes || !sawElements) {
    throwFileError("MESHFILE_3", file,
                   sawNodes ? "the file has no $Elements section" : "the file has no $Nodes section");
  }
  if (g.mesh.cellCount() == 0) {
    throwFileError("MESHFILE_3", file, "the mesh has no cells");
  }
  g.mesh.setDimension(g.allZero ? 2 : 3);
  for (auto& [name, cells] : g.groups) {
    const auto nodes = g.mesh.nodesOfCells(cells);
    g.mesh.setCellGroup(name, std::move(cells));
    g.mesh.setNodeGroup(name, nodes);
  }
  return std::move(g.mesh);
}

} // namespace stella
