// MODI_MAILLAGE: modifies a mesh in place (reuse=MA): ORIE_PEAU (and the 2020 spellings
// ORIE_PEAU_2D/ORIE_PEAU_3D, mapped by the catalogue) orients skin cells outward, ORIE_NORM_COQUE
// and ORIE_LIGNE orient shells and lines consistently (along VECT_NORM / VECT_TANG at GROUP_NO),
// DEFORME moves the nodes by the DEPL field of a result's step, then TRANSLATION, ROTATION,
// ECHELLE and SYMETRIE move the nodes. Other operations are refused as not implemented yet.

#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/inputs/FieldSelection.hpp"
#include "solver/mesh/CellOrientation.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/MeshTransform.hpp"
#include "solver/operators/MeshOperatorUtil.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace stella {

namespace {

Point3 point(const std::vector<double>& v) {
  return {v.empty() ? 0.0 : v[0], v.size() < 2 ? 0.0 : v[1], v.size() < 3 ? 0.0 : v[2]};
}

// The single node of GROUP_NO (ORIE_NORM_COQUE, ORIE_LIGNE), if given.
std::optional<NodeId> singleNode(const Mesh& mesh, const KeywordTree& occ) {
  if (!occ.has("GROUP_NO")) {
    return std::nullopt;
  }
  const auto nodes = nodesOfGroups(mesh, occ, "GROUP_NO");
  if (nodes.size() != 1) {
    throw UserError(msg::make("MODI_MAILLAGE_2.2", {{"group", occ.text("GROUP_NO")}, {"count", nodes.size()}},
                              occ.locationOf("GROUP_NO")));
  }
  return nodes.front();
}

// ORIE_NORM_COQUE (shells) or ORIE_LIGNE (lines), one occurrence.
void orientOccurrence(OperatorCall& call, Mesh& mesh, const KeywordTree& occ, bool shells) {
  const char* vectorKey = shells ? "VECT_NORM" : "VECT_TANG";
  const auto cells = cellsOfGroups(mesh, occ, "GROUP_MA");
  std::optional<Point3> direction;
  if (occ.has(vectorKey)) {
    direction = point(occ.reals(vectorKey));
  }
  try {
    const auto node = singleNode(mesh, occ);
    const auto r =
        shells ? orientShells(mesh, cells, direction, node) : orientLines(mesh, cells, direction, node);
    call.session.message() << fmt::format("   {}: {} of {} cells reversed ({} connected set{})\n",
                                          shells ? "ORIE_NORM_COQUE" : "ORIE_LIGNE", r.reversed, cells.size(),
                                          r.components, r.components > 1 ? "s" : "");
  } catch (const UserError& e) {
    Diagnostic d = e.first();
    if (!d.location.known()) {
      d.location = occ.location();
    }
    throw UserError(d);
  }
}

// DEFORME: the DEPL field of a result's step (NUME_ORDRE, INST, default the last) moves the nodes.
void deform(OperatorCall& call, Mesh& mesh, const KeywordTree& occ) {
  if (occ.has("DEPL") || occ.has("ALEA")) {
    const char* key = occ.has("DEPL") ? "DEPL" : "ALEA";
    throw UserError(msg::make("MODI_MAILLAGE_1", {{"key", key}}, occ.locationOf(key)));
  }
  const auto c = occ.conceptValue("RESULTAT");
  const auto result = conceptData<Result>(c);
  STELLA_ASSERT(result != nullptr, "RESULTAT holds no result");
  const ResultStep* step = &selectStep(*result, c->name, occ, occ.real("PRECISION"));
  const std::string name = occ.text("NOM_CHAM");
  const Field* f = step->field(name);
  if (f == nullptr || f->support() != FieldSupport::Node) {
    throw UserError(msg::make(
        "MODI_MAILLAGE_3", {{"name", c->name}, {"name_2", name}, {"number", step->number}}, occ.location()));
  }
  if (result->mesh.get() != &mesh &&
      (result->mesh == nullptr || result->mesh->nodeCount() != mesh.nodeCount())) {
    throw UserError(msg::make("MODI_MAILLAGE_4", {{"name", c->name}}, occ.location()));
  }
  const char* axes[3] = {"DX", "DY", "DZ"};
  int moved = 0;
  for (NodeId n = 0; n < mesh.nodeCount() && static_cast<std::size_t>(n) < f->entityCount(); ++n) {
    Point3 x = mesh.point(n);
    bool any = false;
    for (int d = 0; d < 3; ++d) {
      const auto k = f->componentIndex(axes[d]);
      if (k && (!f->partial() || f->defined(static_cast<std::size_t>(n), *k))) {
        x[static_cast<std::size_t>(d)] += f->value(static_cast<std::size_t>(n), *k);
        any = true;
      }
    }
    mesh.setPoint(n, x);
    moved += any ? 1 : 0;
  }
  call.session.message() << fmt::format("   DEFORME: {} nodes moved by {} of {} at NUME_ORDRE {} (INST {})\n",
                                        moved, name, c->name, step->number, step->time);
}

// ORIE_PEAU_4: skin cells that bound no volume cell and touch no skin cell that does (a rigid
// surface on its own): oriented coherently among themselves only.
Diagnostic unanchoredSkinAlarm(const Mesh& mesh, const KeywordTree& occ, const std::vector<CellId>& cells) {
  std::vector<std::string> groups;
  for (const auto& g : occ.texts("GROUP_MA_PEAU")) {
    const auto* ids = mesh.cellGroup(g);
    if (ids != nullptr && std::any_of(cells.begin(), cells.end(), [&](CellId c) {
          return std::find(ids->begin(), ids->end(), c) != ids->end();
        })) {
      groups.push_back(g);
    }
  }
  return msg::make("ORIE_PEAU_4",
                   {{"cells_count", cells.size()},
                    {"format", fmt::format("'{}'", fmt::join(groups, "', '"))},
                    {"cell_name", mesh.cellName(cells.front())}},
                   occ.location());
}

Value runModiMaillage(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  auto data = meshConceptOf(kw);
  Mesh& mesh = *data->mesh;
  for (const char* unsupported : {"ORIE_FISSURE", "MODI_MAILLE", "MODI_BASE", "ABSC_CURV"}) {
    if (kw.has(unsupported)) {
      throw UserError(
          msg::make("MODI_MAILLAGE_1.2", {{"unsupported", unsupported}}, kw.locationOf(unsupported)));
    }
  }
  for (const auto& occ : kw.occurrences("ORIE_PEAU")) {
    const auto skin = cellsOfGroups(mesh, occ, "GROUP_MA_PEAU");
    const auto side =
        occ.has("GROUP_MA_INTERNE") ? cellsOfGroups(mesh, occ, "GROUP_MA_INTERNE") : std::vector<CellId>{};
    try {
      const auto summary = orientSkin(mesh, skin, side);
      call.session.message() << fmt::format("   ORIE_PEAU: {} of {} skin cells reoriented\n",
                                            summary.reversed, skin.size());
      if (!summary.unanchored.empty()) {
        call.session.report(unanchoredSkinAlarm(mesh, occ, summary.unanchored));
      }
    } catch (const UserError& e) {
      Diagnostic d = e.first();
      d.location = occ.location();
      throw UserError(d);
    }
  }
  for (const auto& occ : kw.occurrences("ORIE_NORM_COQUE")) {
    orientOccurrence(call, mesh, occ, true);
  }
  for (const auto& occ : kw.occurrences("ORIE_LIGNE")) {
    orientOccurrence(call, mesh, occ, false);
  }
  for (const auto& occ : kw.occurrences("DEFORME")) {
    deform(call, mesh, occ);
  }
  if (kw.has("TRANSLATION")) {
    translateMesh(mesh, point(kw.reals("TRANSLATION")));
  }
  for (const auto& occ : kw.occurrences("ROTATION")) {
    const Point3 p1 = point(occ.reals("POIN_1"));
    Point3 axis{0, 0, 1};
    if (occ.has("DIR")) {
      axis = point(occ.reals("DIR"));
    } else if (occ.has("POIN_2")) {
      axis = point(occ.reals("POIN_2")) - p1;
    }
    rotateMesh(mesh, p1, axis, occ.real("ANGLE"));
  }
  if (kw.has("ECHELLE")) {
    scaleMesh(mesh, kw.real("ECHELLE"));
  }
  for (const auto& occ : kw.occurrences("SYMETRIE")) {
    const Point3 axis1 = point(occ.reals("AXE_1"));
    if (occ.has("AXE_2")) {
      const Point3 axis2 = point(occ.reals("AXE_2"));
      mirrorMesh(mesh, point(occ.reals("POINT")), axis1, &axis2);
    } else {
      mirrorMesh(mesh, point(occ.reals("POINT")), axis1, nullptr);
    }
  }
  return call.makeConcept(data);
}

} // namespace

STELLA_OPERATOR("MODI_MAILLAGE", runModiMaillage);

} // namespace stella
