// LIRE_MAILLAGE: reads the mesh of a logical unit (default 20) in FORMAT MED (NOM_MED selects
// one mesh of the file), ASTER, GMSH or GIBI (Cast3M), runs the VERI_MAIL checks (alarms) and prints a
// summary.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/MeshConcept.hpp"
#include "solver/io/MeshIO.hpp"
#include "solver/mesh/MeshCheck.hpp"
#include "solver/mesh/MeshSummary.hpp"
#include "solver/operators/CoincidentNodesAlarm.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {

MeshFormat formatOf(const KeywordTree& kw) {
  const std::string f = kw.text("FORMAT");
  if (f == "MED") {
    return MeshFormat::Med;
  }
  if (f == "ASTER") {
    return MeshFormat::Aster;
  }
  if (f == "GMSH") {
    return MeshFormat::Gmsh;
  }
  if (f == "GIBI") {
    return MeshFormat::Gibi;
  }
  throw UserError(msg::make("LIRE_MAILLAGE_1", {{"f", f}}, kw.locationOf("FORMAT")));
}

Value runLireMaillage(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  const MeshFormat format = formatOf(kw);
  const auto path =
      call.session.unitPath(static_cast<int>(kw.integer("UNITE")), kw.locationOf("UNITE"), true);
  auto mesh = std::make_shared<Mesh>();
  try {
    *mesh = readMesh(path, format, kw.textOr("NOM_MED", ""));
  } catch (const UserError& e) {
    std::vector<Diagnostic> ds = e.diagnostics();
    for (auto& d : ds) {
      if (!d.location.known()) {
        d.location = call.location;
      }
    }
    throw UserError(ds);
  }
  if (mesh->name().empty() || format != MeshFormat::Med) {
    mesh->setName(call.resultName);
  }
  const auto& veri = kw.occurrences("VERI_MAIL");
  if (!veri.empty() && veri.front().text("VERIF") == "OUI") {
    auto report = checkMesh(*mesh, veri.front().real("APLAT"));
    if (!report.duplicateNodes.empty()) {
      // Held until FIN: a DEFI_CONTACT may join them (CoincidentNodesAlarm.hpp).
      call.session.defer(std::make_shared<CoincidentNodesAlarm>(*mesh, report.duplicateNodes, call.location));
      report.duplicateNodes.clear();
    }
    for (auto d : meshCheckDiagnostics(*mesh, report)) {
      d.location = call.location;
      call.session.report(d);
    }
  }
  if (kw.integer("INFO") >= 1) {
    call.session.message() << meshSummary(*mesh, call.resultName, kw.integer("INFO") >= 2);
  }
  return call.makeConcept(std::make_shared<MeshConcept>(mesh));
}

} // namespace

STELLA_OPERATOR("LIRE_MAILLAGE", runLireMaillage);

} // namespace stella
