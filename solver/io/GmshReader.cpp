// Gmsh .msh reader: formats 2.2 and 4.1, ASCII and binary (gmsh -bin; little-endian, data size
// 8). Physical groups become cell groups (named by $PhysicalNames, else "GM<tag>") and node
// groups of the same name; node and cell names are N<tag> and M<tag> from the file's tags.
//
// Binary files keep the section markers, $PhysicalNames and (in 2.2) the node and element counts
// as text; the rest is raw: in 2.2 every integer is a 4-byte int; in 4.1 tags of entities,
// dimensions, types and physical tags are 4-byte ints while counts and node and element tags
// are 8-byte size_t. Numbers reads either representation through one interface.

#include "solver/io/GmshCellTypes.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/TextScanner.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace stella {

namespace {

// Numbers of a section, text or binary. int32() is a C int in binary files, size() a size_t.
class Numbers {
public:
  Numbers(TextScanner& s, bool binary) : s_(s), binary_(binary) {}
  TextScanner& scanner() { return s_; }
  bool binary() const { return binary_; }
  // Start of a binary block: its data begins after the current line.
  void start() {
    if (binary_) {
      s_.startBinary();
    }
  }
  std::int64_t int32(const char* what) { return binary_ ? s_.binaryInteger(4, what) : s_.integer(what); }
  std::int64_t size(const char* what) { return binary_ ? s_.binaryInteger(8, what) : s_.integer(what); }
  std::int64_t count(const char* what, std::int64_t bytesPerItem) {
    return binary_ ? s_.binaryCount(what, bytesPerItem) : s_.count(what, bytesPerItem);
  }
  double real(const char* what) { return binary_ ? s_.binaryReal(what) : s_.real(what); }

private:
  TextScanner& s_;
  bool binary_;
};

// Maps the file's node tags to node indices, densely when the tags allow it.
class NodeTags {
public:
  void add(std::int64_t tag, NodeId index, TextScanner& s) {
    if (tag <= 0) {
      s.failContent("MESHFILE_3.31", {{"tag", std::to_string(tag)}});
    }
    if (!map_.emplace(tag, index).second) {
      s.failContent("MESHFILE_3.32", {{"tag", std::to_string(tag)}});
    }
  }
  NodeId find(std::int64_t tag, TextScanner& s) const {
    const auto it = map_.find(tag);
    if (it == map_.end()) {
      s.failContent("MESHFILE_3.33", {{"tag", std::to_string(tag)}});
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

void skipSection(TextScanner& s, std::string_view name, bool binary) {
  const std::string end = "$End" + std::string(name.substr(1));
  if (binary) {
    if (!s.skipPastLine(end)) {
      s.fail("MESHFILE_2.7", {{"name", std::string(name)}, {"end", end}});
    }
    return;
  }
  for (auto t = s.next(); t != end; t = s.next()) {
    if (t.empty()) {
      s.fail("MESHFILE_2.7", {{"name", std::string(name)}, {"end", end}});
    }
  }
}

void expectEnd(TextScanner& s, const char* end) {
  const auto t = s.expect(end);
  if (t != end) {
    s.fail("MESHFILE_2.8", {{"end", end}, {"substr", std::string(t.substr(0, 40))}});
  }
}

void readPhysicalNames(TextScanner& s, GmshContent& g) {
  const auto n = s.count("number of physical names", 6);
  for (std::int64_t i = 0; i < n; ++i) {
    const int dim = static_cast<int>(s.integer("physical dimension"));
    const int tag = static_cast<int>(s.integer("physical tag"));
    const auto name = s.expect("physical name");
    if (dim < 0 || dim > 3) {
      s.failContent("MESHFILE_3.34", {{"dim", std::to_string(dim)}});
    }
    g.physicalNames[{dim, tag}] = std::string(name);
  }
  expectEnd(s, "$EndPhysicalNames");
}

Point3 readPoint(Numbers& r, GmshContent& g) {
  Point3 x{};
  x[0] = r.real("node x coordinate");
  x[1] = r.real("node y coordinate");
  x[2] = r.real("node z coordinate");
  g.allZero = g.allZero && x[2] == 0.0;
  return x;
}

void addNode(TextScanner& s, GmshContent& g, std::int64_t tag, const Point3& x) {
  const NodeId id = g.mesh.addNode(x, "N" + std::to_string(tag));
  g.nodes.add(tag, id, s);
}

// The element's node tags are read as int (2.2) or size_t (4.1) values.
CellId addElement(Numbers& r, GmshContent& g, std::int64_t tag, int gmshType, bool sizeTags) {
  TextScanner& s = r.scanner();
  const auto type = cellTypeFromGmsh(gmshType);
  if (!type) {
    s.failContent("MESHFILE_3.35", {{"tag", std::to_string(tag)}, {"gmsh_type", std::to_string(gmshType)}});
  }
  const int n = nodeCount(*type);
  NodeId gmshNodes[27];
  for (int i = 0; i < n; ++i) {
    const auto t = sizeTags ? r.size("element node tag") : r.int32("element node tag");
    gmshNodes[i] = g.nodes.find(t, s);
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
      s.failContent("MESHFILE_3.36", {{"tag", std::to_string(tag)}});
    }
    return it->second;
  }
  return g.mesh.addCell(*type, span, "M" + std::to_string(tag));
}

// ---- format 2.2

void readNodes22(Numbers& r, GmshContent& g) {
  TextScanner& s = r.scanner();
  const auto n = s.count("number of nodes", r.binary() ? 28 : 8);
  g.mesh.reserveNodes(static_cast<NodeId>(n));
  r.start();
  for (std::int64_t i = 0; i < n; ++i) {
    const auto tag = r.int32("node tag");
    addNode(s, g, tag, readPoint(r, g));
  }
  expectEnd(s, "$EndNodes");
}

void addElement22(Numbers& r, GmshContent& g, std::int64_t tag, int type, int physical) {
  const CellId c = addElement(r, g, tag, type, false);
  if (physical != 0) {
    g.groups[groupName(g, dimension(*cellTypeFromGmsh(type)), physical)].push_back(c);
  }
}

void checkTagCount(TextScanner& s, std::int64_t tag, std::int64_t ntags) {
  if (ntags < 0 || ntags > 100) {
    s.failContent("MESHFILE_3.37", {{"tag", std::to_string(tag)}, {"ntags", std::to_string(ntags)}});
  }
}

void readElements22(TextScanner& s, GmshContent& g) {
  Numbers r(s, false);
  const auto n = s.count("number of elements", 8);
  for (std::int64_t i = 0; i < n; ++i) {
    const auto tag = s.integer("element tag");
    const int type = static_cast<int>(s.integer("element type"));
    const auto ntags = s.integer("number of element tags");
    checkTagCount(s, tag, ntags);
    int physical = 0;
    for (std::int64_t k = 0; k < ntags; ++k) {
      const auto v = s.integer("element tag value");
      if (k == 0) {
        physical = static_cast<int>(v);
      }
    }
    addElement22(r, g, tag, type, physical);
  }
  expectEnd(s, "$EndElements");
}

// Binary 2.2: blocks of elements of one type, each headed by (type, count, number of tags).
void readElements22Binary(TextScanner& s, GmshContent& g) {
  Numbers r(s, true);
  const auto n = s.count("number of elements", 12);
  r.start();
  std::int64_t read = 0;
  while (read < n) {
    const int type = static_cast<int>(r.int32("element type"));
    const auto follow = r.int32("number of elements in block");
    const auto ntags = r.int32("number of element tags");
    if (follow <= 0 || follow > n - read) {
      s.failContent("MESHFILE_3.38", {{"follow", std::to_string(follow)}, {"n", std::to_string(n - read)}});
    }
    for (std::int64_t i = 0; i < follow; ++i) {
      const auto tag = r.int32("element tag");
      checkTagCount(s, tag, ntags);
      int physical = 0;
      for (std::int64_t k = 0; k < ntags; ++k) {
        const auto v = r.int32("element tag value");
        if (k == 0) {
          physical = static_cast<int>(v);
        }
      }
      addElement22(r, g, tag, type, physical);
    }
    read += follow;
  }
  expectEnd(s, "$EndElements");
}

// ---- format 4.1

void readEntities41(Numbers& r, GmshContent& g) {
  r.start();
  std::int64_t counts[4];
  for (auto& c : counts) {
    c = r.count("number of entities", 8);
  }
  for (int dim = 0; dim < 4; ++dim) {
    for (std::int64_t i = 0; i < counts[dim]; ++i) {
      const int tag = static_cast<int>(r.int32("entity tag"));
      const int reals = dim == 0 ? 3 : 6;
      for (int k = 0; k < reals; ++k) {
        r.real("entity bounding box");
      }
      const auto nphys = r.count("number of physical tags", 2);
      auto& phys = g.entityPhysicals[{dim, tag}];
      for (std::int64_t k = 0; k < nphys; ++k) {
        phys.push_back(static_cast<int>(r.int32("physical tag")));
      }
      if (dim > 0) {
        const auto nb = r.count("number of bounding entities", 2);
        for (std::int64_t k = 0; k < nb; ++k) {
          r.int32("bounding entity tag");
        }
      }
    }
  }
  expectEnd(r.scanner(), "$EndEntities");
}

void readNodes41(Numbers& r, GmshContent& g) {
  TextScanner& s = r.scanner();
  r.start();
  const auto blocks = r.count("number of node blocks", 8);
  const auto total = r.count("number of nodes", 8);
  r.size("minimum node tag");
  r.size("maximum node tag");
  g.mesh.reserveNodes(static_cast<NodeId>(total));
  std::vector<std::int64_t> tags;
  for (std::int64_t b = 0; b < blocks; ++b) {
    const auto dim = r.int32("entity dimension");
    r.int32("entity tag");
    const auto parametric = r.int32("parametric flag");
    const auto n = r.count("number of nodes in block", 8);
    if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1) {
      s.failContent("MESHFILE_3.39", {});
    }
    tags.resize(static_cast<std::size_t>(n));
    for (auto& t : tags) {
      t = r.size("node tag");
    }
    for (const auto t : tags) {
      addNode(s, g, t, readPoint(r, g));
      for (std::int64_t k = 0; k < parametric * dim; ++k) {
        r.real("node parametric coordinate");
      }
    }
  }
  if (g.mesh.nodeCount() != total) {
    s.failContent("MESHFILE_3.40",
                  {{"total", std::to_string(total)}, {"node_count", std::to_string(g.mesh.nodeCount())}});
  }
  expectEnd(s, "$EndNodes");
}

void readElements41(Numbers& r, GmshContent& g) {
  TextScanner& s = r.scanner();
  r.start();
  const auto blocks = r.count("number of element blocks", 8);
  const auto total = r.count("number of elements", 4);
  r.size("minimum element tag");
  r.size("maximum element tag");
  std::int64_t read = 0;
  for (std::int64_t b = 0; b < blocks; ++b) {
    const int dim = static_cast<int>(r.int32("entity dimension"));
    const int entity = static_cast<int>(r.int32("entity tag"));
    const int type = static_cast<int>(r.int32("element type"));
    const auto n = r.count("number of elements in block", 4);
    const auto it = g.entityPhysicals.find({dim, entity});
    for (std::int64_t i = 0; i < n; ++i) {
      const auto tag = r.size("element tag");
      const CellId c = addElement(r, g, tag, type, true);
      if (it != g.entityPhysicals.end()) {
        for (const int p : it->second) {
          g.groups[groupName(g, dim, p)].push_back(c);
        }
      }
    }
    read += n;
  }
  if (read != total) {
    s.failContent("MESHFILE_3.41", {{"total", std::to_string(total)}, {"read", std::to_string(read)}});
  }
  expectEnd(s, "$EndElements");
}

} // namespace

Mesh readGmshMesh(const std::filesystem::path& file) {
  TextScanner s(file, readWholeFile(file));
  GmshContent g;
  if (s.next() != "$MeshFormat") {
    s.fail("MESHFILE_2.9", {});
  }
  const auto version = s.expect("format version");
  const bool v2 = version.substr(0, 2) == "2.";
  const bool v4 = version == "4.1";
  if (!v2 && !v4) {
    throwFileError("MESHFILE_5.3", file, {{"substr", std::string(version.substr(0, 20))}}, s.line());
  }
  const auto fileType = s.integer("file type");
  const auto dataSize = s.integer("data size");
  const bool binary = fileType == 1;
  if (fileType != 0 && !binary) {
    s.failContent("MESHFILE_3.42", {{"file_type", std::to_string(fileType)}});
  }
  if (binary) {
    if (dataSize != 8) {
      throwFileError("MESHFILE_5.4", file, {{"data_size", std::to_string(dataSize)}}, s.line());
    }
    s.startBinary();
    const auto one = s.binaryInteger(4, "the binary byte-order mark (int 1)");
    if (one != 1) {
      throwFileError("MESHFILE_5.5", file, {{"one", std::to_string(one)}}, s.line());
    }
  }
  expectEnd(s, "$EndMeshFormat");
  Numbers numbers(s, binary);
  bool sawNodes = false;
  bool sawElements = false;
  for (auto t = s.next(); !t.empty(); t = s.next()) {
    if (t == "$PhysicalNames") {
      readPhysicalNames(s, g);
    } else if (t == "$Entities" && v4) {
      readEntities41(numbers, g);
    } else if (t == "$Nodes") {
      if (sawNodes) {
        s.fail("MESHFILE_2.10", {});
      }
      v4 ? readNodes41(numbers, g) : readNodes22(numbers, g);
      sawNodes = true;
    } else if (t == "$Elements") {
      if (!sawNodes) {
        s.fail("MESHFILE_2.11", {});
      }
      if (sawElements) {
        s.fail("MESHFILE_2.12", {});
      }
      if (v4) {
        readElements41(numbers, g);
      } else {
        binary ? readElements22Binary(s, g) : readElements22(s, g);
      }
      sawElements = true;
    } else if (t.size() > 1 && t[0] == '$' && t.substr(0, 4) != "$End") {
      skipSection(s, t, binary);
    } else {
      s.fail("MESHFILE_2.13", {{"substr", std::string(t.substr(0, 40))}});
    }
  }
  if (!sawNodes || !sawElements) {
    throwFileError(sawNodes ? "MESHFILE_3.gmsh_elements" : "MESHFILE_3.gmsh_nodes", file);
  }
  if (g.mesh.cellCount() == 0) {
    throwFileError("MESHFILE_3.2", file, {});
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
