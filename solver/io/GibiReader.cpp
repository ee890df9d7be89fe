// GIBI reader: Cast3M's ASCII save files (SAUVER FORMATTE, .mgib/.sauv), the mesh part only.
//
// The file is a sequence of records, each introduced by a line " ENREGISTREMENT DE TYPE   n":
// type 4 gives the space dimension (" NIVEAU ... DIMENSION   d"), type 2 holds one pile
// (" PILE NUMERO   p NBRE OBJETS NOMMES   n NBRE OBJETS   m", then the n object names in
// FORMAT(8(1X,A8)) and their n object indices in FORMAT(10I8)), type 5 ends the data. Piles read:
//   1   meshes: per object a line (element type, sub-object count, reference count, nodes per
//       element, element count), then the sub-object indices, the references, the element
//       colours and the connectivity (element by element), all FORMAT(10I8). Type 0 with
//       sub-objects is a compound object, the union of its parts.
//   32  nodes: the count, then the coordinate entry of each node number (FORMAT(10I8)).
//   33  coordinates: the count of reals, then per coordinate entry the dim coordinates and a
//       density (FORMAT(1P,3E22.14)).
// Every other pile is skipped. As code_aster's PRE_GIBI does: every point is a node named
// N<number>; every element a cell (POI1 included), numbered in file order; every named mesh
// object a GROUP_MA of the same name (a compound object: the cells of its parts); every named
// point a GROUP_NO of one node. An element listed again (same type and nodes) is the same cell.
// Cast3M element types and node orders are mapped to code_aster's (quadratic elements list their
// nodes corner, middle, corner...); orientations are kept. Every malformed line gives
// MESHFILE_2/3 with the file and line, never a crash.

#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <string_view>

namespace stella {

namespace {

struct GibiType {
  int number;
  const char* name;
  CellType type;
  std::vector<int> perm; // aster node j = Cast3M node perm[j]
};

const std::vector<GibiType>& gibiTypes() {
  static const std::vector<GibiType> types{
      {1, "POI1", CellType::POI1, {0}},
      {2, "SEG2", CellType::SEG2, {0, 1}},
      {3, "SEG3", CellType::SEG3, {0, 2, 1}},
      {4, "TRI3", CellType::TRIA3, {0, 1, 2}},
      {6, "TRI6", CellType::TRIA6, {0, 2, 4, 1, 3, 5}},
      {8, "QUA4", CellType::QUAD4, {0, 1, 2, 3}},
      {10, "QUA8", CellType::QUAD8, {0, 2, 4, 6, 1, 3, 5, 7}},
      {14, "CUB8", CellType::HEXA8, {0, 1, 2, 3, 4, 5, 6, 7}},
      {15, "CU20", CellType::HEXA20, {0, 2, 4, 6, 12, 14, 16, 18, 1, 3, 5, 7, 8, 9, 10, 11, 13, 15, 17, 19}},
      {16, "PRI6", CellType::PENTA6, {0, 2, 1, 3, 5, 4}},
      {17, "PR15", CellType::PENTA15, {0, 4, 2, 9, 13, 11, 5, 3, 1, 6, 7, 8, 14, 12, 10}},
      {23, "TET4", CellType::TETRA4, {0, 2, 1, 3}},
      {24, "TE10", CellType::TETRA10, {0, 4, 2, 9, 5, 3, 1, 6, 8, 7}},
      {25, "PYR5", CellType::PYRAM5, {0, 3, 2, 1, 4}},
      {26, "PY13", CellType::PYRAM13, {0, 6, 4, 2, 12, 7, 5, 3, 1, 8, 11, 10, 9}},
  };
  return types;
}

const GibiType* gibiType(std::int64_t number) {
  for (const auto& t : gibiTypes()) {
    if (t.number == number) {
      return &t;
    }
  }
  return nullptr;
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) {
    s.remove_prefix(1);
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

// Line-oriented reading of the fixed formats, with the line number of every value.
class GibiLines {
public:
  GibiLines(std::filesystem::path file, std::string text) : file_(std::move(file)), text_(std::move(text)) {}

  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) {
      return false;
    }
    const auto end = text_.find('\n', pos_);
    const auto stop = end == std::string::npos ? text_.size() : end;
    line = std::string_view(text_).substr(pos_, stop - pos_);
    if (!line.empty() && line.back() == '\r') {
      line.remove_suffix(1);
    }
    if (line.find('\0') != std::string_view::npos) {
      ++line_;
      fail("MESHFILE_2.14", {});
    }
    pos_ = stop + 1;
    ++line_;
    return true;
  }

  std::string_view expectLine(const std::string& what) {
    std::string_view line;
    if (!next(line)) {
      fail("MESHFILE_2.4", {{"what", what}});
    }
    return line;
  }

  // `n` integers in FORMAT(10I8): 8-character fields, so that wide numbers that touch are read.
  std::vector<std::int64_t> integers(std::int64_t n, const std::string& what) {
    std::vector<std::int64_t> values;
    values.reserve(static_cast<std::size_t>(std::min<std::int64_t>(n, 1 << 20)));
    while (static_cast<std::int64_t>(values.size()) < n) {
      const auto line = expectLine(what);
      for (std::size_t at = 0; at < line.size(); at += 8) {
        const auto field = trimmed(line.substr(at, 8));
        if (field.empty()) {
          continue;
        }
        if (static_cast<std::int64_t>(values.size()) == n) {
          fail("MESHFILE_2.15", {{"what", what}});
        }
        std::int64_t v = 0;
        const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
        if (ec != std::errc() || end != field.data() + field.size()) {
          fail("MESHFILE_2.16", {{"what", what},
                                 {"at", std::to_string(at + 1)},
                                 {"at_2", std::to_string(at + 8)},
                                 {"field", std::string(field)}});
        }
        values.push_back(v);
      }
    }
    return values;
  }

  // `n` reals separated by blanks (FORMAT(1P,3E22.14)); Fortran forms 1.5D+00 and 1.5-100 too.
  std::vector<double> reals(std::int64_t n, const std::string& what) {
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(std::min<std::int64_t>(n, 1 << 20)));
    while (static_cast<std::int64_t>(values.size()) < n) {
      const auto line = expectLine(what);
      std::size_t at = 0;
      while (at < line.size()) {
        while (at < line.size() && line[at] == ' ') {
          ++at;
        }
        const auto end = std::min(line.find(' ', at), line.size());
        if (end == at) {
          break;
        }
        if (static_cast<std::int64_t>(values.size()) == n) {
          fail("MESHFILE_2.15", {{"what", what}});
        }
        values.push_back(real(line.substr(at, end - at), what));
        at = end;
      }
    }
    return values;
  }

  // `n` names in FORMAT(8(1X,A8)).
  std::vector<std::string> names(std::int64_t n, const std::string& what) {
    std::vector<std::string> values;
    while (static_cast<std::int64_t>(values.size()) < n) {
      const auto line = expectLine(what);
      for (std::size_t at = 0; at < line.size() && static_cast<std::int64_t>(values.size()) < n; at += 9) {
        const auto field = trimmed(line.substr(at, 9));
        if (!field.empty()) {
          values.emplace_back(field);
        }
      }
    }
    return values;
  }

  // A count read from the file: at most what the file could hold (guards allocations).
  std::int64_t count(std::int64_t value, const std::string& what) const {
    if (value < 0 || value > static_cast<std::int64_t>(text_.size())) {
      failContent("MESHFILE_3.43", {{"what", what}, {"value", std::to_string(value)}});
    }
    return value;
  }

  [[noreturn]] void fail(std::string_view key, msg::Args args = {}) const {
    throwFileError(key, file_, args, line_);
  }
  [[noreturn]] void failContent(std::string_view key, msg::Args args = {}) const {
    throwFileError(key, file_, args, line_);
  }
  int line() const { return line_; }
  const std::filesystem::path& file() const { return file_; }

private:
  double real(std::string_view token, const std::string& what) const {
    std::string s(token);
    for (char& c : s) {
      if (c == 'D' || c == 'd') {
        c = 'E';
      }
    }
    if (s.find_first_of("Ee") == std::string::npos) {
      const auto sign = s.find_last_of("+-");
      if (sign != std::string::npos && sign > 0) {
        s.insert(sign, "E"); // 1.5-100: a three-digit exponent without its letter
      }
    }
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) {
      fail("MESHFILE_2.17", {{"what", what}, {"token", std::string(token)}});
    }
    return v;
  }

  std::filesystem::path file_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

struct GibiObject {
  const GibiType* type = nullptr;  // null for a compound object
  std::vector<std::int64_t> parts; // compound: 1-based object indices
  std::vector<std::int64_t> nodes; // elementary: element-major Cast3M node numbers
  int line = 0;                    // where the object starts
};

struct GibiFile {
  int dimension = 0;
  std::vector<GibiObject> objects;
  std::vector<std::pair<std::string, std::int64_t>> names; // pile 1 names and object indices
  std::vector<std::int64_t> coordinateOf;                  // pile 32: node number - 1 -> entry
  int coordinateOfLine = 0;                                // where its entries start
  std::vector<double> coordinates;                         // pile 33
  int namesLine = 0;
  std::vector<std::pair<std::string, std::int64_t>> pointNames; // pile 32 names and node numbers
  int pointNamesLine = 0;
};

std::int64_t numberAfter(GibiLines& in, std::string_view line, std::string_view label) {
  const auto at = line.find(label);
  if (at == std::string_view::npos) {
    in.fail("MESHFILE_2.18", {{"label", std::string(label)}});
  }
  auto rest = line.substr(at + label.size());
  rest = trimmed(rest);
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), v);
  if (ec != std::errc() || end == rest.data()) {
    in.fail("MESHFILE_2.19", {{"label", std::string(label)}});
  }
  return v;
}

void readPile1(GibiLines& in, GibiFile& f, std::int64_t nobjects) {
  for (std::int64_t o = 0; o < nobjects; ++o) {
    const std::string which = "mesh object " + std::to_string(o + 1);
    const auto head =
        in.integers(5, "the header of " + which + " (type, parts, references, nodes, elements)");
    GibiObject obj;
    obj.line = in.line();
    const auto nparts = in.count(head[1], "the part count of " + which);
    const auto nrefs = in.count(head[2], "the reference count of " + which);
    const auto nper = in.count(head[3], "the node count per element of " + which);
    const auto nelems = in.count(head[4], "the element count of " + which);
    if (head[0] == 0) {
      obj.parts = in.integers(nparts, "the parts of " + which);
    } else {
      obj.type = gibiType(head[0]);
      if (obj.type == nullptr) {
        throwFileError("MESHFILE_5.8", in.file(), {{"which", which}, {"head", std::to_string(head[0])}},
                       obj.line);
      }
      if (nparts != 0) {
        in.failContent("MESHFILE_3.44", {{"which", which}, {"nparts", std::to_string(nparts)}});
      }
      if (nper != static_cast<std::int64_t>(obj.type->perm.size())) {
        in.failContent("MESHFILE_3.45", {{"which", which},
                                         {"name", obj.type->name},
                                         {"nper", std::to_string(nper)},
                                         {"perm_count", std::to_string(obj.type->perm.size())}});
      }
    }
    in.integers(nrefs, "the references of " + which);
    in.integers(nelems, "the element colours of " + which);
    if (obj.type != nullptr) {
      in.count(nelems * nper, "the connectivity size of " + which);
      obj.nodes = in.integers(nelems * nper, "the connectivity of " + which);
    }
    f.objects.push_back(std::move(obj));
  }
}

void readPile(GibiLines& in, std::string_view header, GibiFile& f, std::set<std::int64_t>& seen) {
  const auto pile = numberAfter(in, header, "PILE NUMERO");
  const auto nnamed = in.count(numberAfter(in, header, "NBRE OBJETS NOMMES"), "the named object count");
  const auto after = header.substr(header.find("NBRE OBJETS NOMMES") + 18);
  const auto nobjects = in.count(numberAfter(in, after, "NBRE OBJETS"), "the object count");
  if (!seen.insert(pile).second) {
    return; // a repeated pile (several saved states): the first one is kept
  }
  if (pile != 1 && pile != 32 && pile != 33) {
    return;
  }
  const int namesLine = in.line() + 1;
  const auto names = in.names(nnamed, "the object names of pile " + std::to_string(pile));
  const auto indices = in.integers(nnamed, "the object indices of pile " + std::to_string(pile));
  if (pile == 1) {
    f.namesLine = namesLine;
    for (std::size_t i = 0; i < names.size(); ++i) {
      f.names.emplace_back(names[i], indices[i]);
    }
    readPile1(in, f, nobjects);
  } else if (pile == 32) {
    f.pointNamesLine = namesLine;
    for (std::size_t i = 0; i < names.size(); ++i) {
      f.pointNames.emplace_back(names[i], indices[i]);
    }
    const auto n = in.count(in.integers(1, "the node count of pile 32")[0], "the node count");
    f.coordinateOfLine = in.line() + 1;
    f.coordinateOf = in.integers(n, "the coordinate entries of the nodes (pile 32)");
  } else {
    if (f.dimension == 0) {
      in.failContent("MESHFILE_3.46", {});
    }
    const auto n = in.count(in.integers(1, "the real count of pile 33")[0], "the real count");
    if (n % (f.dimension + 1) != 0) {
      in.failContent("MESHFILE_3.47",
                     {{"n", std::to_string(n)}, {"dimension", std::to_string(f.dimension + 1)}});
    }
    f.coordinates = in.reals(n, "node coordinates (pile 33)");
  }
}

GibiFile parseGibi(const std::filesystem::path& file) {
  GibiLines in(file, readWholeFile(file));
  GibiFile f;
  std::set<std::int64_t> seen;
  bool records = false;
  std::string_view line;
  while (in.next(line)) {
    if (trimmed(line).rfind("ENREGISTREMENT DE TYPE", 0) != 0) {
      continue;
    }
    records = true;
    const auto type = numberAfter(in, line, "ENREGISTREMENT DE TYPE");
    if (type == 5) {
      break;
    }
    if (type == 4) {
      const auto info = in.expectLine("the line ' NIVEAU ... DIMENSION d'");
      f.dimension = static_cast<int>(numberAfter(in, info, "DIMENSION"));
      if (f.dimension != 2 && f.dimension != 3) {
        in.failContent("MESHFILE_3.48", {{"dimension", std::to_string(f.dimension)}});
      }
    } else if (type == 2) {
      readPile(in, in.expectLine("a line ' PILE NUMERO ...'"), f, seen);
    }
  }
  if (!records) {
    throwFileError("MESHFILE_2.2", file, {});
  }
  if (f.objects.empty()) {
    throwFileError("MESHFILE_3.18", file, {});
  }
  if (f.coordinateOf.empty() || f.coordinates.empty()) {
    throwFileError("MESHFILE_3.19", file, {});
  }
  return f;
}

// Every point of pile 32 is a node named N<number>, as code_aster's PRE_GIBI writes them.
void buildNodes(const std::filesystem::path& file, const GibiFile& f, Mesh& mesh) {
  const auto stride = static_cast<std::size_t>(f.dimension + 1);
  const auto entries = static_cast<std::int64_t>(f.coordinates.size() / stride);
  mesh.reserveNodes(static_cast<std::int64_t>(f.coordinateOf.size()));
  for (std::size_t i = 0; i < f.coordinateOf.size(); ++i) {
    const auto entry = f.coordinateOf[i];
    if (entry < 1 || entry > entries) {
      throwFileError("MESHFILE_3.20", file,
                     {{"i", std::to_string(i + 1)},
                      {"entry", std::to_string(entry)},
                      {"entries", std::to_string(entries)}},
                     f.coordinateOfLine + static_cast<int>(i / 10));
    }
    Point3 x{0.0, 0.0, 0.0};
    for (std::size_t d = 0; d < static_cast<std::size_t>(f.dimension); ++d) {
      x[d] = f.coordinates[static_cast<std::size_t>(entry - 1) * stride + d];
    }
    mesh.addNode(x, "N" + std::to_string(i + 1));
  }
}

// The cells of every elementary object (empty for compound objects), in file order; an element
// listed again (same type and nodes) is the cell already made.
std::vector<std::vector<CellId>> buildCells(const std::filesystem::path& file, const GibiFile& f,
                                            Mesh& mesh) {
  std::vector<std::vector<CellId>> cells(f.objects.size());
  std::map<std::pair<CellType, std::vector<NodeId>>, CellId> known;
  const auto nnodes = static_cast<std::int64_t>(f.coordinateOf.size());
  for (std::size_t o = 0; o < f.objects.size(); ++o) {
    const auto& obj = f.objects[o];
    if (obj.type == nullptr) {
      continue;
    }
    const auto& perm = obj.type->perm;
    const std::size_t nn = perm.size();
    for (std::size_t e = 0; e * nn < obj.nodes.size(); ++e) {
      std::vector<NodeId> nodes(nn);
      for (std::size_t j = 0; j < nn; ++j) {
        const auto n = obj.nodes[e * nn + static_cast<std::size_t>(perm[j])];
        if (n < 1 || n > nnodes) {
          throwFileError(
              "MESHFILE_3.21", file,
              {{"o", std::to_string(o + 1)}, {"n", std::to_string(n)}, {"nnodes", std::to_string(nnodes)}},
              obj.line);
        }
        nodes[j] = static_cast<NodeId>(n - 1);
      }
      auto key = std::make_pair(obj.type->type, nodes);
      std::sort(key.second.begin(), key.second.end());
      const auto [it, added] = known.emplace(std::move(key), 0);
      if (added) {
        it->second = mesh.addCell(obj.type->type, nodes);
      }
      cells[o].push_back(it->second);
    }
  }
  return cells;
}

// The elementary objects of object `o` (itself, or its parts recursively).
void collectParts(const std::filesystem::path& file, const GibiFile& f, std::int64_t o, int depth,
                  std::vector<std::size_t>& out) {
  const auto& obj = f.objects[static_cast<std::size_t>(o)];
  if (obj.type != nullptr) {
    out.push_back(static_cast<std::size_t>(o));
    return;
  }
  if (depth > 64) {
    throwFileError("MESHFILE_3.22", file, {{"o", std::to_string(o + 1)}}, obj.line);
  }
  for (const auto p : obj.parts) {
    if (p < 1 || p > static_cast<std::int64_t>(f.objects.size())) {
      throwFileError("MESHFILE_3.23", file,
                     {{"o", std::to_string(o + 1)},
                      {"p", std::to_string(p)},
                      {"objects_count", std::to_string(f.objects.size())}},
                     obj.line);
    }
    collectParts(file, f, p - 1, depth + 1, out);
  }
}

// Named mesh objects become GROUP_MA (the cells of their elementary parts), named points
// GROUP_NO of one node, as code_aster's PRE_GIBI does.
void buildGroups(const std::filesystem::path& file, const GibiFile& f,
                 const std::vector<std::vector<CellId>>& cells, Mesh& mesh) {
  for (const auto& [name, index] : f.names) {
    if (index < 1 || index > static_cast<std::int64_t>(f.objects.size())) {
      throwFileError("MESHFILE_3.24", file,
                     {{"name", name},
                      {"index", std::to_string(index)},
                      {"objects_count", std::to_string(f.objects.size())}},
                     f.namesLine);
    }
    std::vector<std::size_t> parts;
    collectParts(file, f, index - 1, 0, parts);
    std::set<CellId> members;
    for (const auto p : parts) {
      members.insert(cells[p].begin(), cells[p].end());
    }
    mesh.setCellGroup(name, std::vector<CellId>(members.begin(), members.end()));
  }
  for (const auto& [name, number] : f.pointNames) {
    if (number < 1 || number > static_cast<std::int64_t>(f.coordinateOf.size())) {
      throwFileError("MESHFILE_3.25", file,
                     {{"name", name},
                      {"number", std::to_string(number)},
                      {"coordinate_of_count", std::to_string(f.coordinateOf.size())}},
                     f.pointNamesLine);
    }
    mesh.setNodeGroup(name, std::vector<NodeId>{static_cast<NodeId>(number - 1)});
  }
}

} // namespace

Mesh readGibiMesh(const std::filesystem::path& file) {
  const GibiFile f = parseGibi(file);
  Mesh mesh;
  mesh.setDimension(f.dimension);
  buildNodes(file, f, mesh);
  const auto cells = buildCells(file, f, mesh);
  if (mesh.cellCount() == 0) {
    throwFileError("MESHFILE_3.26", file, {});
  }
  buildGroups(file, f, cells, mesh);
  return mesh;
}

} // namespace stella
