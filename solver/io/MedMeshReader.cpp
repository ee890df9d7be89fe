// MED mesh reader (libmedC): nodes, cells of every supported geometry (MED_CELL entities, node
// orderings mapped to code_aster's), node and cell names when present, families mapped to
// groups of nodes and cells (MED 3/4 layout, and the MED 2.3 layout of older Salome versions
// through the library's 2.3 family call). Cells are numbered in increasing MED geometry order,
// as code_aster does. Every library failure becomes MESHFILE_4 naming the file and the step.

#include "messages/Messages.hpp"
#include "solver/io/MedCommon.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"

#include <cmath>
#include <map>

namespace stella {

namespace {

struct MeshHeader {
  std::string name;
  med_int spaceDim = 0;
  med_int meshDim = 0;
  med_mesh_type type = MED_UNSTRUCTURED_MESH;
};

std::vector<MeshHeader> readHeaders(const MedFile& f) {
  const med_int n = MEDnMesh(f.id());
  f.check(n, "MEDnMesh", "counting meshes");
  std::vector<MeshHeader> headers;
  for (med_int i = 1; i <= n; ++i) {
    const med_int naxis = MEDmeshnAxis(f.id(), static_cast<int>(i));
    f.check(naxis, "MEDmeshnAxis", "mesh " + std::to_string(i));
    if (naxis < 1 || naxis > 3) {
      throwFileError("MESHFILE_3.7", f.path(), {{"i", std::to_string(i)}, {"naxis", std::to_string(naxis)}});
    }
    MeshHeader h;
    char name[MED_NAME_SIZE + 1] = {};
    char description[MED_COMMENT_SIZE + 1] = {};
    char dtunit[MED_SNAME_SIZE + 1] = {};
    std::vector<char> axisName(static_cast<std::size_t>(naxis) * MED_SNAME_SIZE + 1, '\0');
    std::vector<char> axisUnit(static_cast<std::size_t>(naxis) * MED_SNAME_SIZE + 1, '\0');
    med_sorting_type sorting{};
    med_int nstep = 0;
    med_axis_type axis{};
    f.check(MEDmeshInfo(f.id(), static_cast<int>(i), name, &h.spaceDim, &h.meshDim, &h.type, description,
                        dtunit, &sorting, &nstep, &axis, axisName.data(), axisUnit.data()),
            "MEDmeshInfo", "mesh " + std::to_string(i));
    h.name = medName(name, MED_NAME_SIZE);
    headers.push_back(h);
  }
  return headers;
}

med_int entityCount(const MedFile& f, const std::string& mesh, med_entity_type entity, med_geometry_type geo,
                    med_data_type data) {
  med_bool changed = MED_FALSE;
  med_bool transformed = MED_FALSE;
  const med_int n = MEDmeshnEntity(f.id(), mesh.c_str(), MED_NO_DT, MED_NO_IT, entity, geo, data, MED_NODAL,
                                   &changed, &transformed);
  f.check(n, "MEDmeshnEntity", "mesh " + mesh);
  return n;
}

std::vector<std::string> readNames(const MedFile& f, const std::string& mesh, med_entity_type entity,
                                   med_geometry_type geo, med_int n) {
  std::vector<std::string> names;
  if (entityCount(f, mesh, entity, geo, MED_NAME) != n || n == 0) {
    return names;
  }
  std::vector<char> buffer(static_cast<std::size_t>(n) * MED_SNAME_SIZE + 1, '\0');
  f.check(MEDmeshEntityNameRd(f.id(), mesh.c_str(), MED_NO_DT, MED_NO_IT, entity, geo, buffer.data()),
          "MEDmeshEntityNameRd", "names in mesh " + mesh);
  names.reserve(static_cast<std::size_t>(n));
  for (med_int i = 0; i < n; ++i) {
    names.push_back(medName(buffer.data() + static_cast<std::size_t>(i) * MED_SNAME_SIZE, MED_SNAME_SIZE));
    if (names.back().empty()) {
      return {}; // incomplete names: use default ones
    }
  }
  return names;
}

std::vector<med_int> readFamilies(const MedFile& f, const std::string& mesh, med_entity_type entity,
                                  med_geometry_type geo, med_int n) {
  std::vector<med_int> fam;
  if (n == 0 || entityCount(f, mesh, entity, geo, MED_FAMILY_NUMBER) != n) {
    return fam;
  }
  fam.resize(static_cast<std::size_t>(n));
  f.check(MEDmeshEntityFamilyNumberRd(f.id(), mesh.c_str(), MED_NO_DT, MED_NO_IT, entity, geo, fam.data()),
          "MEDmeshEntityFamilyNumberRd", "families in mesh " + mesh);
  return fam;
}

// Files of the MED 2.x layout (older Salome): families live under the mesh and may carry
// attributes; the library reads them with MEDfamily23Info only (MEDfamilyInfo has no 2.x
// implementation). The attributes (identifier, value, description) mean nothing to code_aster.
bool hasLayout23(const MedFile& f) {
  med_int major = 0;
  med_int minor = 0;
  med_int release = 0;
  f.check(MEDfileNumVersionRd(f.id(), &major, &minor, &release), "MEDfileNumVersionRd", "file version");
  return major < 3;
}

void readFamily23(const MedFile& f, const std::string& mesh, int family, med_int& number,
                  std::vector<char>& names) {
  const std::string context = "family " + std::to_string(family) + " of mesh " + mesh;
  const med_int nattr = MEDnFamily23Attribute(f.id(), mesh.c_str(), family);
  f.check(nattr, "MEDnFamily23Attribute", context);
  if (nattr > 100000) {
    throwFileError("MESHFILE_3.8", f.path(), {{"context", context}, {"nattr", std::to_string(nattr)}});
  }
  const auto na = static_cast<std::size_t>(nattr);
  std::vector<med_int> ids(na + 1);
  std::vector<med_int> values(na + 1);
  std::vector<char> descriptions(na * MED_COMMENT_SIZE + 1, '\0');
  char famName[MED_NAME_SIZE + 1] = {};
  f.check(MEDfamily23Info(f.id(), mesh.c_str(), family, famName, ids.data(), values.data(),
                          descriptions.data(), &number, names.data()),
          "MEDfamily23Info", context);
}

std::map<med_int, std::vector<std::string>> readFamilyGroups(const MedFile& f, const std::string& mesh) {
  std::map<med_int, std::vector<std::string>> groups;
  const bool layout23 = hasLayout23(f);
  const med_int nfam = MEDnFamily(f.id(), mesh.c_str());
  f.check(nfam, "MEDnFamily", "mesh " + mesh);
  for (med_int i = 1; i <= nfam; ++i) {
    const med_int ngroup = MEDnFamilyGroup(f.id(), mesh.c_str(), static_cast<int>(i));
    f.check(ngroup, "MEDnFamilyGroup", "family " + std::to_string(i) + " of mesh " + mesh);
    if (ngroup > 100000) {
      throwFileError("MESHFILE_3.9", f.path(),
                     {{"i", std::to_string(i)}, {"ngroup", std::to_string(ngroup)}});
    }
    med_int number = 0;
    std::vector<char> names(static_cast<std::size_t>(ngroup) * MED_LNAME_SIZE + 1, '\0');
    if (layout23) {
      readFamily23(f, mesh, static_cast<int>(i), number, names);
    } else {
      char famName[MED_NAME_SIZE + 1] = {};
      f.check(MEDfamilyInfo(f.id(), mesh.c_str(), static_cast<int>(i), famName, &number, names.data()),
              "MEDfamilyInfo", "family " + std::to_string(i) + " of mesh " + mesh);
    }
    auto& list = groups[number];
    for (med_int g = 0; g < ngroup; ++g) {
      const auto n = medName(names.data() + static_cast<std::size_t>(g) * MED_LNAME_SIZE, MED_LNAME_SIZE);
      if (!n.empty()) {
        list.push_back(n);
      }
    }
  }
  return groups;
}

void addToGroups(const std::map<med_int, std::vector<std::string>>& families, med_int family, std::int32_t id,
                 std::map<std::string, std::vector<std::int32_t>>& groups) {
  if (family == 0) {
    return;
  }
  const auto it = families.find(family);
  if (it == families.end()) {
    return; // a family without a definition carries no group
  }
  for (const auto& g : it->second) {
    groups[g].push_back(id);
  }
}

} // namespace

std::vector<std::string> medMeshNames(const std::filesystem::path& file) {
  const StderrSilencer quiet;
  const MedFile f(file, MedFile::Mode::Read);
  std::vector<std::string> names;
  for (const auto& h : readHeaders(f)) {
    names.push_back(h.name);
  }
  return names;
}

namespace {

// The file cannot hold more than its size in values: counts beyond that come from a damaged
// header and must not drive allocations.
void checkPlausible(const MedFile& f, std::uint64_t values, std::size_t bytesEach, const std::string& what) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(f.path(), ec);
  if (!ec && values * bytesEach > 4 * size + (1u << 20)) {
    throwFileError("MESHFILE_3.10", f.path(), {{"what", what}, {"values", std::to_string(values)}});
  }
}

Mesh readMedMeshUnguarded(const std::filesystem::path& file, const std::string& meshName);

} // namespace

Mesh readMedMesh(const std::filesystem::path& file, const std::string& meshName) {
  const StderrSilencer quiet;
  try {
    return readMedMeshUnguarded(file, meshName);
  } catch (const std::bad_alloc&) {
    throwFileError("MESHFILE_3.11", file, {});
  } catch (const std::length_error&) {
    throwFileError("MESHFILE_3.11", file, {});
  }
}

namespace {

Mesh readMedMeshUnguarded(const std::filesystem::path& file, const std::string& meshName) {
  const MedFile f(file, MedFile::Mode::Read);
  const auto headers = readHeaders(f);
  if (headers.empty()) {
    throwFileError("MESHFILE_3.12", file, {});
  }
  const MeshHeader* header = &headers.front();
  if (!meshName.empty()) {
    header = nullptr;
    std::string available;
    for (const auto& h : headers) {
      available += (available.empty() ? "" : ", ") + h.name;
      if (h.name == meshName) {
        header = &h;
      }
    }
    if (header == nullptr) {
      throw UserError(msg::make(
          "MESHFILE_6", {{"file", file.string()}, {"mesh_name", meshName}, {"available", available}}));
    }
  }
  if (header->type != MED_UNSTRUCTURED_MESH) {
    throwFileError("MESHFILE_5", file, {{"name", header->name}});
  }
  const std::string& name = header->name;
  const auto families = readFamilyGroups(f, name);
  Mesh mesh;
  mesh.setName(name);
  mesh.setDimension(header->spaceDim == 3 ? 3 : 2);

  // Nodes.
  const med_int nnodes = entityCount(f, name, MED_NODE, MED_NONE, MED_COORDINATE);
  if (nnodes <= 0) {
    throwFileError("MESHFILE_3.13", file, {{"name", name}});
  }
  const auto sd = static_cast<std::size_t>(header->spaceDim);
  checkPlausible(f, static_cast<std::uint64_t>(nnodes) * sd, sizeof(med_float), "coordinates");
  std::vector<med_float> coords(static_cast<std::size_t>(nnodes) * sd);
  f.check(
      MEDmeshNodeCoordinateRd(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, MED_FULL_INTERLACE, coords.data()),
      "MEDmeshNodeCoordinateRd", "coordinates of mesh " + name);
  const auto nodeNames = readNames(f, name, MED_NODE, MED_NONE, nnodes);
  mesh.reserveNodes(nnodes);
  for (med_int i = 0; i < nnodes; ++i) {
    Point3 x{0.0, 0.0, 0.0};
    for (std::size_t d = 0; d < sd; ++d) {
      x[d] = coords[static_cast<std::size_t>(i) * sd + d];
      if (!std::isfinite(x[d])) {
        throwFileError("MESHFILE_3.14", file, {{"i", std::to_string(i + 1)}});
      }
    }
    if (nodeNames.empty()) {
      mesh.addNode(x);
    } else {
      mesh.addNode(x, nodeNames[static_cast<std::size_t>(i)]);
    }
  }
  std::map<std::string, std::vector<std::int32_t>> nodeGroups;
  const auto nodeFamilies = readFamilies(f, name, MED_NODE, MED_NONE, nnodes);
  for (std::size_t i = 0; i < nodeFamilies.size(); ++i) {
    addToGroups(families, nodeFamilies[i], static_cast<std::int32_t>(i), nodeGroups);
  }

  // Cells, by increasing MED geometry type.
  std::map<std::string, std::vector<std::int32_t>> cellGroups;
  med_int knownCells = 0;
  for (const CellType t : medCellOrder()) {
    const med_geometry_type geo = medGeometryOf(t);
    const med_int n = entityCount(f, name, MED_CELL, geo, MED_CONNECTIVITY);
    if (n <= 0) {
      continue;
    }
    knownCells += n;
    const auto nn = static_cast<std::size_t>(nodeCount(t));
    checkPlausible(f, static_cast<std::uint64_t>(n) * nn, sizeof(med_int),
                   std::string(stella::name(t)) + " cells");
    std::vector<med_int> conn(static_cast<std::size_t>(n) * nn);
    f.check(MEDmeshElementConnectivityRd(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, geo, MED_NODAL,
                                         MED_FULL_INTERLACE, conn.data()),
            "MEDmeshElementConnectivityRd", std::string(stella::name(t)) + " cells of mesh " + name);
    const auto names = readNames(f, name, MED_CELL, geo, n);
    const auto fams = readFamilies(f, name, MED_CELL, geo, n);
    const auto perm = medPermutation(t);
    NodeId nodes[27];
    for (med_int c = 0; c < n; ++c) {
      for (std::size_t j = 0; j < nn; ++j) {
        const med_int v = conn[static_cast<std::size_t>(c) * nn + static_cast<std::size_t>(perm[j])];
        if (v < 1 || v > nnodes) {
          throwFileError("MESHFILE_3.15", file,
                         {{"name", std::string(stella::name(t))},
                          {"c", std::to_string(c + 1)},
                          {"v", std::to_string(v)},
                          {"nnodes", std::to_string(nnodes)}});
        }
        nodes[j] = v - 1;
      }
      const std::span<const NodeId> span(nodes, nn);
      const CellId id =
          names.empty() ? mesh.addCell(t, span) : mesh.addCell(t, span, names[static_cast<std::size_t>(c)]);
      if (!fams.empty()) {
        addToGroups(families, fams[static_cast<std::size_t>(c)], id, cellGroups);
      }
    }
  }
  // Geometry types stella does not know (polygons, polyhedra...).
  const med_int ntypes = entityCount(f, name, MED_CELL, MED_GEO_ALL, MED_CONNECTIVITY);
  for (med_int i = 1; i <= ntypes; ++i) {
    char geoName[MED_NAME_SIZE + 1] = {};
    med_geometry_type geo = MED_NONE;
    f.check(MEDmeshEntityInfo(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, static_cast<int>(i),
                              geoName, &geo),
            "MEDmeshEntityInfo", "cell types of mesh " + name);
    if (const auto t = cellTypeFromMed(geo);
        t && entityCount(f, name, MED_CELL, geo, MED_CONNECTIVITY) <= 0) {
      throwFileError("MESHFILE_3.16", file, {{"name", name}, {"name_2", std::string(stella::name(*t))}});
    }
    if (!cellTypeFromMed(geo)) {
      throwFileError(
          "MESHFILE_5.2", file,
          {{"name", name}, {"med_name", medName(geoName, MED_NAME_SIZE)}, {"geo", std::to_string(geo)}});
    }
  }
  if (mesh.cellCount() == 0) {
    throwFileError("MESHFILE_3.17", file, {{"name", name}});
  }
  for (auto& [g, ids] : cellGroups) {
    mesh.setCellGroup(g, std::move(ids));
  }
  for (auto& [g, ids] : nodeGroups) {
    mesh.setNodeGroup(g, std::move(ids));
  }
  return mesh;
}

} // namespace

} // namespace stella
