// IMPR_RESU: writes meshes and results. FORMAT='MED' (unit 80; successive calls on one unit add
// to the file), 'RESULTAT' (text tables, unit 8 = the result file), 'GMSH' (unit 37), 'VTU'
// (stella's extension: the unit's file is a .pvd collection with one .vtu per step beside it) and
// 'ASTER' (unit 26: the mesh of RESU=_F(MAILLAGE=...) as a .mail file that LIRE_MAILLAGE
// FORMAT='ASTER' reads back; fields in that format are refused as not implemented yet).
// RESU occurrences: MAILLAGE alone, or RESULTAT with NOM_CHAM, NUME_ORDRE / INST / TOUT_ORDRE
// and NOM_CMP selections; GROUP_NO / GROUP_MA restrict the rows of FORMAT='RESULTAT'. Gauss points get the
// coordinates of the code_aster RIGI family.

#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/fem/Quadrature.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/io/ResultWriters.hpp"
#include "solver/io/RigiPoints.hpp"
#include "solver/operators/MeshOperatorUtil.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace stella {

namespace {

std::vector<int> selectedSteps(const Result& r, const KeywordTree& occ) {
  std::vector<int> numbers;
  if (occ.has("NUME_ORDRE")) {
    for (const auto n : occ.integers("NUME_ORDRE")) {
      if (r.stepNumber(static_cast<int>(n)) == nullptr) {
        throw UserError(msg::make("IMPR_RESU_2", {{"n", std::to_string(n)}}, occ.locationOf("NUME_ORDRE")));
      }
      numbers.push_back(static_cast<int>(n));
    }
  }
  if (occ.has("INST")) {
    const bool absolute = occ.text("CRITERE") == "ABSOLU";
    const double precision = occ.real("PRECISION");
    for (const double t : occ.reals("INST")) {
      const ResultStep* s = r.stepAtTime(t, precision, absolute);
      if (s == nullptr) {
        throw UserError(msg::make("IMPR_RESU_2.2", {{"t", std::to_string(t)}}, occ.locationOf("INST")));
      }
      numbers.push_back(s->number);
    }
  }
  return numbers;
}

// FORMAT_R: the Fortran edit descriptor of the printed values ('1PE21.14' by default).
RealEditDescriptor valueFormat(const KeywordTree& occ) {
  const std::string text = occ.text("FORMAT_R");
  const auto d = parseRealEditDescriptor(text);
  if (!d) {
    throw UserError(msg::make("IMPR_RESU_5", {{"text", text}}, occ.locationOf("FORMAT_R")));
  }
  return *d;
}

struct Target {
  std::filesystem::path path; // empty: the text result file (unit 8) or the message file (unit 6)
  std::string format;
  bool messageFile = false;
  std::array<int, 3> medVersion{0, 0, 0}; // FORMAT='MED'
};

// GROUP_NO / GROUP_MA (FORMAT='RESULTAT'): nodal fields are printed on the nodes of GROUP_NO and
// of the cells of GROUP_MA; cell and point fields on the cells of GROUP_MA, or, with GROUP_NO
// alone, on the cells that hold one of its nodes. The other formats write every node and cell
// (alarm IMPR_RESU_4).
void restrictToGroups(OperatorCall& call, const Target& target, const KeywordTree& occ, const Mesh& mesh,
                      ResultOutput& out) {
  if (!occ.has("GROUP_NO") && !occ.has("GROUP_MA")) {
    return;
  }
  if (target.format != "RESULTAT") {
    call.session.report(msg::make("IMPR_RESU_4", {{"format", target.format}},
                                  occ.locationOf(occ.has("GROUP_NO") ? "GROUP_NO" : "GROUP_MA")));
    return;
  }
  out.nodes.assign(static_cast<std::size_t>(mesh.nodeCount()), false);
  out.cells.assign(static_cast<std::size_t>(mesh.cellCount()), false);
  for (const auto& g : occ.texts("GROUP_MA")) {
    const auto* cells = mesh.cellGroup(g);
    if (cells == nullptr) {
      throw UserError(msg::make("GROUP_1.2", {{"g", g}}, occ.locationOf("GROUP_MA")));
    }
    for (const CellId c : *cells) {
      out.cells[static_cast<std::size_t>(c)] = true;
      for (const NodeId n : mesh.cellNodes(c)) {
        out.nodes[static_cast<std::size_t>(n)] = true;
      }
    }
  }
  for (const auto& g : occ.texts("GROUP_NO")) {
    const auto* nodes = mesh.nodeGroup(g);
    if (nodes == nullptr) {
      throw UserError(msg::make("GROUP_2.2", {{"g", g}}, occ.locationOf("GROUP_NO")));
    }
    for (const NodeId n : *nodes) {
      out.nodes[static_cast<std::size_t>(n)] = true;
    }
  }
  if (!occ.has("GROUP_MA")) {
    for (CellId c = 0; c < mesh.cellCount(); ++c) {
      for (const NodeId n : mesh.cellNodes(c)) {
        if (out.nodes[static_cast<std::size_t>(n)]) {
          out.cells[static_cast<std::size_t>(c)] = true;
          break;
        }
      }
    }
  }
}

// VERSION_MED ('3.3.1', '4.0.0', '4.1.0': the catalogue's values) as {major, minor, release}.
std::array<int, 3> medVersion(const KeywordTree& kw) {
  const std::string text = kw.text("VERSION_MED");
  std::array<int, 3> v{0, 0, 0};
  const int read = std::sscanf(text.c_str(), "%d.%d.%d", &v[0], &v[1], &v[2]);
  STELLA_ASSERT(read == 3, "VERSION_MED is not major.minor.release");
  return v;
}

void writeOccurrence(OperatorCall& call, const Target& target, const KeywordTree& occ, bool& fileStarted) {
  std::shared_ptr<const Mesh> mesh;
  std::shared_ptr<Result> result;
  std::string resultName = "RESU";
  if (occ.has("CHAM_GD")) {
    throw UserError(msg::make("IMPR_RESU_1", {}, occ.locationOf("CHAM_GD")));
  }
  if (occ.has("RESULTAT")) {
    const auto c = occ.conceptValue("RESULTAT");
    result = conceptData<Result>(c);
    STELLA_ASSERT(result != nullptr, "RESULTAT holds no result");
    mesh = result->mesh;
    resultName = c->name;
  }
  if (occ.has("MAILLAGE")) {
    mesh = meshConceptOf(occ)->mesh;
  }
  STELLA_ASSERT(mesh != nullptr, "IMPR_RESU without a mesh");
  ResultOutput out;
  out.resultName = occ.textOr("NOM_RESU_MED", resultName);
  if (occ.has("NOM_CHAM")) {
    out.fields = occ.texts("NOM_CHAM");
  }
  if (occ.has("NOM_CMP")) {
    out.components = occ.texts("NOM_CMP");
  }
  if (result) {
    out.steps = selectedSteps(*result, occ);
    const auto known = result->fieldNames();
    for (const auto& f : out.fields) {
      if (std::find(known.begin(), known.end(), f) == known.end()) {
        call.session.report(
            msg::make("IMPR_RESU_3", {{"result_name", resultName}, {"f", f}}, occ.locationOf("NOM_CHAM")));
      }
    }
  }
  if (target.format == "RESULTAT") {
    out.valueFormat = valueFormat(occ);
  }
  out.medVersion = target.medVersion;
  out.gaussPoints = rigiGaussPoints;
  restrictToGroups(call, target, occ, *mesh, out);
  const Result* r = result.get();
  if (target.format == "MED") {
    writeMedResult(target.path, *mesh, mesh->name(), r, out, fileStarted);
  } else if (target.format == "VTU") {
    writeVtuResult(target.path, *mesh, r, out);
  } else if (target.format == "GMSH") {
    writeGmshResult(target.path, *mesh, r, out);
  } else if (target.format == "RESULTAT") {
    const std::string text = r != nullptr ? formatResultTables(*mesh, *r, out) : std::string();
    if (target.messageFile) {
      call.session.message() << text;
    } else if (target.path.empty()) {
      call.session.result() << text;
    } else {
      std::ofstream f(target.path, std::ios::app);
      f << text;
    }
  }
  fileStarted = true;
}

// FORMAT='ASTER': one mesh (RESU=_F(MAILLAGE=...)) per call, written as a .mail file; the title
// holds the mesh's name and SOUS_TITRE. Fields, MODELE, CARA_ELEM and FORMAT_R (the edit
// descriptor of field values) are refused: only the mesh is implemented.
void writeAsterFormat(OperatorCall& call, const std::filesystem::path& path) {
  const KeywordTree& kw = call.keywords;
  const auto refuse = [](const KeywordTree& where, const std::string& keyword, const std::string& what) {
    throw UserError(msg::make("IMPR_RESU_1.2", {{"what", what}}, where.locationOf(keyword)));
  };
  if (kw.has("MODELE")) {
    refuse(kw, "MODELE", "MODELE");
  }
  const auto& occurrences = kw.occurrences("RESU");
  if (occurrences.size() > 1) {
    refuse(occurrences[1], "MAILLAGE", msg::text("IMPR_RESU_1.f1"));
  }
  for (const auto& occ : occurrences) {
    for (const char* k : {"RESULTAT", "CHAM_GD", "CARA_ELEM"}) {
      if (occ.has(k)) {
        refuse(occ, k, k);
      }
    }
    if (const auto* f = occ.simple("FORMAT_R"); f != nullptr && !f->defaulted) {
      refuse(occ, "FORMAT_R", msg::text("IMPR_RESU_1.f2"));
    }
    const auto mesh = meshConceptOf(occ);
    const std::string meshName = occ.conceptValue("MAILLAGE")->name;
    std::vector<std::string> title{"mesh " + meshName + " written by stella IMPR_RESU"};
    if (occ.has("SOUS_TITRE")) {
      title.push_back(occ.text("SOUS_TITRE"));
    }
    writeAsterMesh(path, *mesh->mesh, title);
    call.session.message() << "  IMPR_RESU: mesh " << meshName << " written in the ASTER format to "
                           << path.filename().string() << "\n";
  }
}

Value runImprResu(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  Target target{{}, kw.text("FORMAT")};
  if (target.format == "ASTER") {
    writeAsterFormat(
        call, call.session.unitPath(static_cast<int>(kw.integer("UNITE")), kw.locationOf("UNITE"), false));
    return Value();
  }
  if (target.format == "IDEAS") {
    throw UserError(msg::make("IMPR_RESU_1.3", {{"format", target.format}}, kw.locationOf("FORMAT")));
  }
  if (target.format == "GMSH" && kw.real("VERSION") != 2.2) {
    // The catalogue refuses 1.0 and 1.2 (hors_perimetre): this guards a catalogue change.
    throw UserError(msg::make("IMPR_RESU_1.4", {{"real", kw.real("VERSION")}}, kw.locationOf("VERSION")));
  }
  const int unit = static_cast<int>(kw.integer("UNITE")); // each FORMAT block of the catalogue defaults it
  target.messageFile = target.format == "RESULTAT" && unit == 6;
  if (!(target.format == "RESULTAT" && (unit == 8 || unit == 6))) {
    target.path = call.session.unitPath(unit, kw.locationOf("UNITE"), false);
  }
  if (target.format == "MED") {
    target.medVersion = medVersion(kw);
  }
  std::error_code ec;
  bool started = target.format == "MED" && std::filesystem::file_size(target.path, ec) > 0 && !ec;
  for (const auto& occ : kw.occurrences("RESU")) {
    writeOccurrence(call, target, occ, started);
  }
  return Value();
}

} // namespace

STELLA_OPERATOR("IMPR_RESU", runImprResu);

} // namespace stella
