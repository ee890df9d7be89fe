// MED result writer (see ResultWriters.hpp): the mesh, then for each field one MED field with
// its components and one time step per stored step. Gauss-point fields carry a localisation per
// cell type (reference coordinates in MED's node order, points from the GaussPointProvider);
// cell-node fields are written on MED_NODE_ELEMENT with the nodes in MED's order.

#include "messages/Messages.hpp"
#include "solver/io/MedCommon.hpp"
#include "solver/io/MedMeshWriterDetail.hpp"
#include "solver/io/MeshFileError.hpp"
#include "solver/io/ResultWriters.hpp"
#include "solver/job/CopyBack.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/session/ExceptionDiagnostic.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace stella {

namespace {

std::vector<const ResultStep*> selectedSteps(const Result* result, const ResultOutput& out) {
  std::vector<const ResultStep*> steps;
  if (result == nullptr) {
    return steps;
  }
  for (const auto& s : result->steps) {
    if (out.steps.empty() || std::find(out.steps.begin(), out.steps.end(), s.number) != out.steps.end()) {
      steps.push_back(&s);
    }
  }
  return steps;
}

std::vector<std::string> selectedFields(const Result* result, const ResultOutput& out) {
  if (result == nullptr) {
    return {};
  }
  return out.fields.empty() ? result->fieldNames() : out.fields;
}

bool meshInFile(const MedFile& f, const std::string& name) {
  const med_int n = MEDnMesh(f.id());
  for (med_int i = 1; i <= n; ++i) {
    const med_int naxis = MEDmeshnAxis(f.id(), static_cast<int>(i));
    if (naxis < 1 || naxis > 3) {
      continue;
    }
    char meshName[MED_NAME_SIZE + 1] = {};
    char description[MED_COMMENT_SIZE + 1] = {};
    char dtunit[MED_SNAME_SIZE + 1] = {};
    std::vector<char> axis(static_cast<std::size_t>(naxis) * MED_SNAME_SIZE + 1, '\0');
    std::vector<char> unit(axis.size(), '\0');
    med_int sd = 0, md = 0, nstep = 0;
    med_mesh_type type{};
    med_sorting_type sorting{};
    med_axis_type axisType{};
    if (MEDmeshInfo(f.id(), static_cast<int>(i), meshName, &sd, &md, &type, description, dtunit, &sorting,
                    &nstep, &axisType, axis.data(), unit.data()) >= 0 &&
        medName(meshName, MED_NAME_SIZE) == name) {
      return true;
    }
  }
  return false;
}

class FieldWriter {
public:
  FieldWriter(const MedFile& f, const Mesh& mesh, const std::string& meshName, const ResultOutput& out)
      : f_(f), mesh_(mesh), meshName_(meshName), out_(out), order_(medWriteOrder(mesh)) {}

  // Components kept by NOM_CMP (all when no filter).
  std::vector<std::size_t> keptComponents(const Field& field) const {
    std::vector<std::size_t> k;
    for (std::size_t c = 0; c < field.componentCount(); ++c) {
      if (out_.components.empty() || std::find(out_.components.begin(), out_.components.end(),
                                               field.components()[c]) != out_.components.end()) {
        k.push_back(c);
      }
    }
    return k;
  }

  void create(const std::string& name, const Field& field) {
    const auto kept = keptComponents(field);
    std::string names;
    for (const auto c : kept) {
      names += medPadded(field.components()[c], MED_SNAME_SIZE);
    }
    const std::string units(kept.size() * MED_SNAME_SIZE, ' ');
    f_.check(MEDfieldCr(f_.id(), name.c_str(), MED_FLOAT64, static_cast<med_int>(kept.size()), names.c_str(),
                        units.c_str(), "", meshName_.c_str()),
             "MEDfieldCr", "field " + name);
  }

  void write(const std::string& name, const Field& field, const ResultStep& step) {
    const auto kept = keptComponents(field);
    if (kept.empty()) {
      return;
    }
    switch (field.support()) {
    case FieldSupport::Node:
      writeNodal(name, field, step, kept);
      return;
    case FieldSupport::Cell:
      writePerCell(name, field, step, kept);
      return;
    case FieldSupport::GaussPoint:
    case FieldSupport::CellNode:
      writePerPoint(name, field, step, kept);
      return;
    }
  }

private:
  std::string profile(const std::vector<med_int>& numbers) {
    const std::string p = "PFL_" + std::to_string(++profiles_);
    f_.check(MEDprofileWr(f_.id(), p.c_str(), static_cast<med_int>(numbers.size()), numbers.data()),
             "MEDprofileWr", "profile " + p);
    return p;
  }

  void values(const std::string& name, const ResultStep& step, med_entity_type entity, med_geometry_type geo,
              const std::string& pfl, const std::string& loc, med_int n, const std::vector<med_float>& v) {
    f_.check(MEDfieldValueWithProfileWr(f_.id(), name.c_str(), step.number, MED_NO_IT, step.time, entity, geo,
                                        MED_COMPACT_STMODE, pfl.c_str(), loc.c_str(), MED_FULL_INTERLACE,
                                        MED_ALL_CONSTITUENT, n,
                                        reinterpret_cast<const unsigned char*>(v.data())),
             "MEDfieldValueWithProfileWr", "field " + name + " step " + std::to_string(step.number));
  }

  void writeNodal(const std::string& name, const Field& field, const ResultStep& step,
                  const std::vector<std::size_t>& kept) {
    std::vector<med_float> v;
    std::vector<med_int> numbers;
    for (std::size_t e = 0; e < field.entityCount(); ++e) {
      bool any = !field.partial();
      for (const auto c : kept) {
        any = any || field.defined(e, c);
      }
      if (!any) {
        continue;
      }
      numbers.push_back(static_cast<med_int>(e + 1));
      for (const auto c : kept) {
        v.push_back(!field.partial() || field.defined(e, c) ? field.value(e, c) : 0.0);
      }
    }
    if (numbers.empty()) {
      return;
    }
    const bool all = numbers.size() == static_cast<std::size_t>(mesh_.nodeCount());
    values(name, step, MED_NODE, MED_NONE, all ? MED_ALLENTITIES_PROFILE : profile(numbers),
           MED_NO_LOCALIZATION, static_cast<med_int>(numbers.size()), v);
  }

  // Cells of each type in written order: (type, [(position in the type block, cell)]).
  std::vector<std::pair<CellType, std::vector<CellId>>> blocks() const {
    std::vector<std::pair<CellType, std::vector<CellId>>> out;
    for (const CellId c : order_) {
      const CellType t = mesh_.cellType(c);
      if (out.empty() || out.back().first != t) {
        out.emplace_back(t, std::vector<CellId>{});
      }
      out.back().second.push_back(c);
    }
    return out;
  }

  void writePerCell(const std::string& name, const Field& field, const ResultStep& step,
                    const std::vector<std::size_t>& kept) {
    // A partial field (CONT_ELEM on the slave cells) is written on the cells where it has a value,
    // through a profile of their positions in their type's block.
    for (const auto& [t, cells] : blocks()) {
      std::vector<med_float> v;
      std::vector<med_int> numbers;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        const auto e = static_cast<std::size_t>(cells[i]);
        bool any = !field.partial();
        for (const auto k : kept) {
          any = any || (e < field.entityCount() && field.defined(e, k));
        }
        if (!any) {
          continue;
        }
        numbers.push_back(static_cast<med_int>(i + 1));
        for (const auto k : kept) {
          v.push_back(e < field.entityCount() && (!field.partial() || field.defined(e, k)) ? field.value(e, k)
                                                                                           : 0.0);
        }
      }
      if (numbers.empty()) {
        continue;
      }
      const bool all = numbers.size() == cells.size();
      values(name, step, MED_CELL, medGeometryOf(t), all ? MED_ALLENTITIES_PROFILE : profile(numbers),
             MED_NO_LOCALIZATION, static_cast<med_int>(numbers.size()), v);
    }
  }

  std::string localization(CellType t, int points) {
    const std::string key = std::string(stella::name(t)) + "_" + std::to_string(points);
    if (localizations_.count(key) != 0) {
      return localizations_[key];
    }
    const std::string loc = "LOC_" + key;
    const auto ref = referenceCoordinates(t);
    const auto perm = medPermutation(t);
    const int dim = dimension(t);
    std::vector<med_float> nodes(ref.size() * static_cast<std::size_t>(dim));
    for (std::size_t j = 0; j < ref.size(); ++j) {
      for (int d = 0; d < dim; ++d) {
        nodes[static_cast<std::size_t>(perm[j]) * static_cast<std::size_t>(dim) +
              static_cast<std::size_t>(d)] = ref[j][static_cast<std::size_t>(d)];
      }
    }
    std::vector<Point3> gauss = out_.gaussPoints ? out_.gaussPoints(t, points) : std::vector<Point3>{};
    if (static_cast<int>(gauss.size()) != points) {
      Point3 centre{0, 0, 0};
      for (int i = 0; i < vertexCount(t); ++i) {
        centre = {centre[0] + ref[static_cast<std::size_t>(i)][0] / vertexCount(t),
                  centre[1] + ref[static_cast<std::size_t>(i)][1] / vertexCount(t),
                  centre[2] + ref[static_cast<std::size_t>(i)][2] / vertexCount(t)};
      }
      gauss.assign(static_cast<std::size_t>(points), centre);
    }
    std::vector<med_float> g;
    for (const auto& p : gauss) {
      for (int d = 0; d < dim; ++d) {
        g.push_back(p[static_cast<std::size_t>(d)]);
      }
    }
    const std::vector<med_float> w(static_cast<std::size_t>(points), 1.0);
    f_.check(MEDlocalizationWr(f_.id(), loc.c_str(), medGeometryOf(t), dim, nodes.data(), MED_FULL_INTERLACE,
                               points, g.data(), w.data(), MED_NO_INTERPOLATION, MED_NO_MESH_SUPPORT),
             "MEDlocalizationWr", "localisation " + loc);
    localizations_[key] = loc;
    return loc;
  }

  void writePerPoint(const std::string& name, const Field& field, const ResultStep& step,
                     const std::vector<std::size_t>& kept) {
    const bool elno = field.support() == FieldSupport::CellNode;
    for (const auto& [t, cells] : blocks()) {
      // Cells of this type carrying points, grouped by point count (one localisation each).
      std::map<int, std::vector<std::pair<med_int, CellId>>> byCount;
      for (std::size_t k = 0; k < cells.size(); ++k) {
        const auto c = static_cast<std::size_t>(cells[k]);
        const int n = c < field.cellCount() ? field.pointCount(c) : 0;
        if (n > 0 && (!elno || n == nodeCount(t))) {
          byCount[n].emplace_back(static_cast<med_int>(k + 1), cells[k]);
        }
      }
      for (const auto& [n, list] : byCount) {
        std::vector<med_float> v;
        std::vector<med_int> numbers;
        const auto perm = medPermutation(t);
        for (const auto& [number, c] : list) {
          numbers.push_back(number);
          const std::size_t first = field.firstPoint(static_cast<std::size_t>(c));
          std::vector<med_float> cellValues(static_cast<std::size_t>(n) * kept.size());
          for (int p = 0; p < n; ++p) {
            // ELNO values follow the cell's nodes: MED position of code_aster node p.
            const std::size_t slot = elno ? static_cast<std::size_t>(perm[static_cast<std::size_t>(p)])
                                          : static_cast<std::size_t>(p);
            for (std::size_t k = 0; k < kept.size(); ++k) {
              const std::size_t e = first + static_cast<std::size_t>(p);
              cellValues[slot * kept.size() + k] =
                  !field.partial() || field.defined(e, kept[k]) ? field.value(e, kept[k]) : 0.0;
            }
          }
          v.insert(v.end(), cellValues.begin(), cellValues.end());
        }
        const bool all = list.size() == cells.size();
        const std::string pfl = all ? std::string(MED_ALLENTITIES_PROFILE) : profile(numbers);
        if (elno) {
          values(name, step, MED_NODE_ELEMENT, medGeometryOf(t), pfl, MED_NO_LOCALIZATION,
                 static_cast<med_int>(list.size()), v);
        } else {
          values(name, step, MED_CELL, medGeometryOf(t), pfl, localization(t, n),
                 static_cast<med_int>(list.size()), v);
        }
      }
    }
  }

  const MedFile& f_;
  const Mesh& mesh_;
  std::string meshName_;
  const ResultOutput& out_;
  std::vector<CellId> order_;
  std::map<std::string, std::string> localizations_;
  int profiles_ = 0;
};

} // namespace

std::string medFieldName(const std::string& resultName, const std::string& field) {
  std::string prefix = resultName.substr(0, 8);
  prefix.resize(8, '_');
  return prefix + field;
}

namespace {

void writeInto(const MedFile& f, const Mesh& mesh, const std::string& meshName, const Result* result,
               const ResultOutput& output, bool append) {
  const std::string name = !meshName.empty() ? meshName : (!mesh.name().empty() ? mesh.name() : "MAIL");
  if (!append || !meshInFile(f, name)) {
    writeMedMeshInto(f, mesh, name);
  }
  FieldWriter writer(f, mesh, name, output);
  const auto steps = selectedSteps(result, output);
  for (const auto& fieldName : selectedFields(result, output)) {
    const std::string medName = medFieldName(output.resultName, fieldName);
    bool created = false;
    for (const ResultStep* s : steps) {
      const Field* field = s->field(fieldName);
      if (field == nullptr) {
        continue;
      }
      if (!created) {
        writer.create(medName, *field);
        created = true;
      }
      writer.write(medName, *field, *s);
    }
  }
}

// A file written under a temporary name beside it, renamed only when complete: a write that
// fails (a full disk, the file-size limit) leaves the file as it was before the call.
class PartialFile {
public:
  PartialFile(const std::filesystem::path& file, bool append)
      : file_(file), partial_(file.string() + ".writing") {
    std::error_code ec;
    std::filesystem::remove(partial_, ec);
    if (append && std::filesystem::exists(file_, ec)) {
      if (auto reason = copyResultFile(file_, partial_)) {
        std::filesystem::remove(partial_, ec);
        throw UserError(msg::make("MESHFILE_7", {{"file", file_.string()}, {"reason", *reason}}));
      }
    }
  }
  ~PartialFile() {
    std::error_code ec;
    std::filesystem::remove(partial_, ec); // left only after a failure
  }
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;
  const std::filesystem::path& path() const { return partial_; }
  void commit() const {
    std::error_code ec;
    std::filesystem::rename(partial_, file_, ec);
    if (ec) {
      throw UserError(msg::make("MESHFILE_7.2", {{"file", file_.string()},
                                                 {"filename", partial_.filename().string()},
                                                 {"os_reason", osReason(ec.value())}}));
    }
  }

private:
  std::filesystem::path file_;
  std::filesystem::path partial_;
};

} // namespace

void writeMedResult(const std::filesystem::path& file, const Mesh& mesh, const std::string& meshName,
                    const Result* result, const ResultOutput& output, bool append) {
  const StderrSilencer quiet;
  const PartialFile partial(file, append);
  try {
    MedFile f(partial.path(), append ? MedFile::Mode::Append : MedFile::Mode::Create, file,
              output.medVersion);
    writeInto(f, mesh, meshName, result, output, append);
    f.close();
  } catch (UserError& e) {
    std::vector<Diagnostic> ds = e.diagnostics();
    std::error_code ec;
    ds.front().withNote(std::filesystem::exists(file, ec) ? msg::text("MESHFILE_7.n2")
                                                          : msg::text("MESHFILE_7.n3"));
    throw UserError(std::move(ds));
  }
  partial.commit();
}

} // namespace stella
