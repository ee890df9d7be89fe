// MED mesh writer (libmedC): coordinates, cells by increasing MED geometry type with code_aster
// orderings mapped to MED's, node and cell names (when they are not the default ones of the
// written order, and fit MED's 16 characters), and groups as families: one family per distinct
// set of groups, positive numbers for nodes, negative for cells, family 0 for none.

#include "solver/io/MedCommon.hpp"
#include "solver/io/MedMeshWriterDetail.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/MeshIO.hpp"

#include <map>
#include <set>

namespace stella {

namespace {

// Family numbers for entities from their group memberships.
struct Families {
  std::vector<med_int> number;                            // per entity
  std::map<std::vector<std::string>, med_int> byGroupSet; // distinct group sets
};

template <class Groups> Families buildFamilies(std::size_t count, const Groups& groups, int sign) {
  std::vector<std::vector<std::string>> member(count);
  for (const auto& [g, ids] : groups) {
    for (const auto id : ids) {
      member[static_cast<std::size_t>(id)].push_back(g); // groups iterate in name order
    }
  }
  Families f;
  f.number.assign(count, 0);
  for (std::size_t i = 0; i < count; ++i) {
    if (member[i].empty()) {
      continue;
    }
    const auto [it, added] = f.byGroupSet.emplace(member[i], 0);
    if (added) {
      it->second = sign * static_cast<med_int>(f.byGroupSet.size());
    }
    f.number[i] = it->second;
  }
  return f;
}

void writeFamilies(const MedFile& f, const std::string& mesh, const Families& fams, const char* prefix) {
  for (const auto& [groups, number] : fams.byGroupSet) {
    std::string names;
    for (const auto& g : groups) {
      if (g.size() > MED_LNAME_SIZE) {
        throwFileError("MESHFILE_7.6", f.path(), {{"g", g}});
      }
      names += medPadded(g, MED_LNAME_SIZE);
    }
    const std::string famName = std::string(prefix) + std::to_string(number < 0 ? -number : number);
    f.check(MEDfamilyCr(f.id(), mesh.c_str(), famName.c_str(), number, static_cast<med_int>(groups.size()),
                        names.c_str()),
            "MEDfamilyCr", "family " + famName);
  }
}

bool namesFit(const NameTable& names) {
  for (std::int32_t i = 0; i < names.size(); ++i) {
    if (names.name(i).size() > MED_SNAME_SIZE) {
      return false;
    }
  }
  return true;
}

} // namespace

std::vector<CellId> medWriteOrder(const Mesh& mesh) {
  std::vector<CellId> order;
  order.reserve(static_cast<std::size_t>(mesh.cellCount()));
  std::vector<std::vector<CellId>> byType(cellTypeCount);
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    byType[static_cast<std::size_t>(mesh.cellType(c))].push_back(c);
  }
  for (const CellType t : medCellOrder()) {
    const auto& list = byType[static_cast<std::size_t>(t)];
    order.insert(order.end(), list.begin(), list.end());
  }
  return order;
}

void writeMedMesh(const std::filesystem::path& file, const Mesh& mesh, const std::string& meshName,
                  bool append) {
  const MedFile f(file, append ? MedFile::Mode::Append : MedFile::Mode::Create);
  writeMedMeshInto(f, mesh, meshName);
}

void writeMedMeshInto(const MedFile& f, const Mesh& mesh, const std::string& requestedName) {
  const std::string name =
      !requestedName.empty() ? requestedName : (!mesh.name().empty() ? mesh.name() : "MAIL");
  if (name.size() > MED_NAME_SIZE) {
    throwFileError("MESHFILE_7.7", f.path(), {{"name", name}});
  }
  const med_int sd = mesh.dimension() == 2 ? 2 : 3;
  const med_int md = std::max(1, mesh.maxCellDimension());
  const std::string axisNames = medPadded("X", MED_SNAME_SIZE) + medPadded("Y", MED_SNAME_SIZE) +
                                (sd == 3 ? medPadded("Z", MED_SNAME_SIZE) : std::string());
  const std::string axisUnits(static_cast<std::size_t>(sd) * MED_SNAME_SIZE, ' ');
  f.check(MEDmeshCr(f.id(), name.c_str(), sd, md, MED_UNSTRUCTURED_MESH, "written by stella", "",
                    MED_SORT_DTIT, MED_CARTESIAN, axisNames.c_str(), axisUnits.c_str()),
          "MEDmeshCr", "mesh " + name);

  // Nodes.
  const auto nn = static_cast<std::size_t>(mesh.nodeCount());
  std::vector<med_float> coords(nn * static_cast<std::size_t>(sd));
  for (std::size_t i = 0; i < nn; ++i) {
    for (std::size_t d = 0; d < static_cast<std::size_t>(sd); ++d) {
      coords[i * static_cast<std::size_t>(sd) + d] = mesh.coordinates()[3 * i + d];
    }
  }
  f.check(MEDmeshNodeCoordinateWr(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, 0.0, MED_FULL_INTERLACE,
                                  static_cast<med_int>(nn), coords.data()),
          "MEDmeshNodeCoordinateWr", "mesh " + name);
  if (!mesh.nodeNames().isDefault() && namesFit(mesh.nodeNames())) {
    std::string names;
    names.reserve(nn * MED_SNAME_SIZE);
    for (NodeId i = 0; i < mesh.nodeCount(); ++i) {
      names += medPadded(mesh.nodeName(i), MED_SNAME_SIZE);
    }
    f.check(MEDmeshEntityNameWr(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE,
                                static_cast<med_int>(nn), names.c_str()),
            "MEDmeshEntityNameWr", "node names of mesh " + name);
  }
  const Families nodeFams = buildFamilies(nn, mesh.nodeGroups(), +1);
  const Families cellFams = buildFamilies(static_cast<std::size_t>(mesh.cellCount()), mesh.cellGroups(), -1);
  f.check(MEDfamilyCr(f.id(), name.c_str(), "FAMILLE_ZERO", 0, 0, ""), "MEDfamilyCr", "family 0");
  writeFamilies(f, name, nodeFams, "FAM_NO_");
  writeFamilies(f, name, cellFams, "FAM_MA_");
  if (!nodeFams.byGroupSet.empty()) {
    f.check(MEDmeshEntityFamilyNumberWr(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, MED_NODE, MED_NONE,
                                        static_cast<med_int>(nn), nodeFams.number.data()),
            "MEDmeshEntityFamilyNumberWr", "node families of mesh " + name);
  }

  // Cells.
  const auto order = medWriteOrder(mesh);
  bool orderKept = true;
  for (std::size_t i = 0; i < order.size(); ++i) {
    orderKept = orderKept && order[i] == static_cast<CellId>(i);
  }
  const bool writeCellNames = (!orderKept || !mesh.cellNames().isDefault()) && namesFit(mesh.cellNames());
  std::size_t k = 0;
  while (k < order.size()) {
    const CellType t = mesh.cellType(order[k]);
    std::size_t end = k;
    while (end < order.size() && mesh.cellType(order[end]) == t) {
      ++end;
    }
    const auto nper = static_cast<std::size_t>(nodeCount(t));
    const auto perm = medPermutation(t);
    std::vector<med_int> conn((end - k) * nper);
    std::vector<med_int> fams(end - k);
    std::string names;
    for (std::size_t i = k; i < end; ++i) {
      const auto nodes = mesh.cellNodes(order[i]);
      for (std::size_t j = 0; j < nper; ++j) {
        conn[(i - k) * nper + static_cast<std::size_t>(perm[j])] = nodes[j] + 1;
      }
      fams[i - k] = cellFams.number[static_cast<std::size_t>(order[i])];
      if (writeCellNames) {
        names += medPadded(mesh.cellName(order[i]), MED_SNAME_SIZE);
      }
    }
    const med_geometry_type geo = medGeometryOf(t);
    const auto n = static_cast<med_int>(end - k);
    const std::string what = std::string(stella::name(t)) + " cells of mesh " + name;
    f.check(MEDmeshElementConnectivityWr(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, 0.0, MED_CELL, geo,
                                         MED_NODAL, MED_FULL_INTERLACE, n, conn.data()),
            "MEDmeshElementConnectivityWr", what);
    if (writeCellNames) {
      f.check(
          MEDmeshEntityNameWr(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, geo, n, names.c_str()),
          "MEDmeshEntityNameWr", what);
    }
    if (!cellFams.byGroupSet.empty()) {
      f.check(MEDmeshEntityFamilyNumberWr(f.id(), name.c_str(), MED_NO_DT, MED_NO_IT, MED_CELL, geo, n,
                                          fams.data()),
              "MEDmeshEntityFamilyNumberWr", what);
    }
    k = end;
  }
}

} // namespace stella
