// MODI_MAILLAGE: modifies a mesh in place (reuse=MA): ORIE_PEAU (and the 2020 spellings
// ORIE_PEAU_2D/ORIE_PEAU_3D, mapped by the catalogue) orients skin cells outward, then
// TRANSLATION, ROTATION, ECHELLE and SYMETRIE move the nodes. Other operations are refused as not
// implemented yet.

#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/MeshTransform.hpp"
#include "solver/operators/MeshOperatorUtil.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

Point3 point(const std::vector<double>& v) {
  return {v.empty() ? 0.0 : v[0], v.size() < 2 ? 0.0 : v[1], v.size() < 3 ? 0.0 : v[2]};
}

Value runModiMaillage(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  auto data = meshConceptOf(kw);
  Mesh& mesh = *data->mesh;
  for (const char* unsupported : {"ORIE_FISSURE", "DEFORME", "ORIE_NORM_COQUE", "ORIE_LIGNE", "MODI_MAILLE",
                                  "MODI_BASE", "ABSC_CURV"}) {
    if (kw.has(unsupported)) {
      throw UserError(Diagnostic::fatal(
          "MODI_MAILLAGE_1", std::string("MODI_MAILLAGE/") + unsupported + " is not implemented yet",
          kw.locationOf(unsupported)));
    }
  }
  for (const auto& occ : kw.occurrences("ORIE_PEAU")) {
    const auto skin = cellsOfGroups(mesh, occ, "GROUP_MA_PEAU");
    const auto side =
        occ.has("GROUP_MA_INTERNE") ? cellsOfGroups(mesh, occ, "GROUP_MA_INTERNE") : std::vector<CellId>{};
    try {
      const int reversed = orientSkin(mesh, skin, side);
      call.session.message() << fmt::format("   ORIE_PEAU: {} of {} skin cells reoriented\n", reversed,
                                            skin.size());
    } catch (const UserError& e) {
      Diagnostic d = e.first();
      d.location = occ.location();
      throw UserError(d);
    }
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
    rotateMesh(mesh, p1, axis, occ.realOr("ANGLE", 0.0));
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
