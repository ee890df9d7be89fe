// DEFI_GROUP: creates and destroys groups of cells and nodes of a mesh, in place (reuse=MA as in
// code_aster: models built on the mesh see the new groups). Order: DETR_GROUP_MA, DETR_GROUP_NO,
// CREA_GROUP_MA, CREA_GROUP_NO, each occurrence in turn. INCLUSION and GRILLE are refused as not
// implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/MeshConcept.hpp"
#include "solver/database/Result.hpp"
#include "solver/inputs/FieldSelection.hpp"
#include "solver/mesh/GroupOperations.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

#include <limits>
#include <numeric>

namespace stella {

namespace {

[[noreturn]] void fail(std::string_view key, msg::Args args, const SourceLocation& at) {
  throw UserError(msg::make(key, args, at));
}

std::string groupList(const std::map<std::string, std::vector<std::int32_t>>& groups) {
  std::string s;
  for (const auto& [g, ids] : groups) {
    s += (s.empty() ? "" : ", ") + g;
    if (s.size() > 300) {
      return s + ", ...";
    }
  }
  return s.empty() ? "(none)" : s;
}

std::vector<CellId> cellGroup(const Mesh& m, const std::string& g, const SourceLocation& at) {
  const auto* v = m.cellGroup(g);
  if (v == nullptr) {
    fail("DEFI_GROUP_1", {{"g", g}, {"group_list", groupList(m.cellGroups())}}, at);
  }
  return *v;
}

std::vector<NodeId> nodeGroup(const Mesh& m, const std::string& g, const SourceLocation& at) {
  const auto* v = m.nodeGroup(g);
  if (v == nullptr) {
    fail("DEFI_GROUP_1.2", {{"g", g}, {"group_list", groupList(m.nodeGroups())}}, at);
  }
  return *v;
}

std::vector<std::vector<std::int32_t>> cellGroups(const Mesh& m, const KeywordTree& occ,
                                                  const std::string& kw) {
  std::vector<std::vector<std::int32_t>> out;
  for (const auto& g : occ.texts(kw)) {
    out.push_back(cellGroup(m, g, occ.locationOf(kw)));
  }
  return out;
}

std::vector<std::vector<std::int32_t>> nodeGroups(const Mesh& m, const KeywordTree& occ,
                                                  const std::string& kw) {
  std::vector<std::vector<std::int32_t>> out;
  for (const auto& g : occ.texts(kw)) {
    out.push_back(nodeGroup(m, g, occ.locationOf(kw)));
  }
  return out;
}

Point3 vectorOf(const std::vector<double>& v) {
  return {v.empty() ? 0.0 : v[0], v.size() < 2 ? 0.0 : v[1], v.size() < 3 ? 0.0 : v[2]};
}

// POINT, the node NOEUD_CENTRE, or the single node of GROUP_NO_CENTRE.
Point3 centreOf(const Mesh& m, const KeywordTree& occ) {
  if (occ.has("POINT")) {
    return vectorOf(occ.reals("POINT"));
  }
  if (occ.has("NOEUD_CENTRE")) {
    const auto name = occ.text("NOEUD_CENTRE");
    const auto id = m.findNode(name);
    if (!id) {
      fail("DEFI_GROUP_2", {{"name", name}}, occ.locationOf("NOEUD_CENTRE"));
    }
    return m.point(*id);
  }
  if (occ.has("GROUP_NO_CENTRE")) {
    const auto nodes = nodeGroup(m, occ.text("GROUP_NO_CENTRE"), occ.locationOf("GROUP_NO_CENTRE"));
    if (nodes.size() != 1) {
      fail("DEFI_GROUP_3", {}, occ.locationOf("GROUP_NO_CENTRE"));
    }
    return m.point(nodes.front());
  }
  fail("DEFI_GROUP_3.2", {}, occ.location());
}

Point3 directionOf(const KeywordTree& occ) {
  return occ.has("VECT_NORMALE") ? vectorOf(occ.reals("VECT_NORMALE"))
                                 : nauticalDirection(occ.reals("ANGL_NAUT"));
}

NodeCriterion criterionOf(const std::string& c) {
  if (c == "TOUS" || c == "TOUT") {
    return NodeCriterion::All;
  }
  if (c == "MAJORITE") {
    return NodeCriterion::Majority;
  }
  if (c == "SOMMET") {
    return NodeCriterion::Vertices;
  }
  return NodeCriterion::AtLeastOne;
}

// CREA_GROUP_MA OPTION='SPHERE', 'CYLINDRE' or 'BANDE': the cells with CRIT_NOEUD of their nodes
// in the sphere, the cylinder or the band.
std::vector<CellId> cellsAround(const Mesh& m, const KeywordTree& occ, const std::string& option,
                                const Point3& centre) {
  const auto all = allCells(m);
  const NodeCriterion crit = criterionOf(occ.text("CRIT_NOEUD"));
  if (option == "SPHERE") {
    const double r = occ.real("RAYON");
    return cellsByNodes(
        m, all, [&](NodeId n) { return norm(m.point(n) - centre) <= r; }, crit);
  }
  if (option == "CYLINDRE") {
    const double r = occ.real("RAYON");
    const Point3 axis = directionOf(occ);
    return cellsByNodes(
        m, all, [&](NodeId n) { return distanceToAxis(m.point(n), centre, axis) <= r; }, crit);
  }
  if (option == "BANDE") {
    const double d = occ.real("DIST");
    const Point3 normal = directionOf(occ);
    return cellsByNodes(
        m, all, [&](NodeId n) { return distanceToPlane(m.point(n), centre, normal) <= d; }, crit);
  }
  return {};
}

std::vector<CellId> optionCells(const Mesh& m, const KeywordTree& occ) {
  const std::string option = occ.text("OPTION");
  const auto all = allCells(m);
  if (option == "FACE_NORMALE") {
    return cellsFacing(m, directionOf(occ), occ.real("ANGL_PREC"), occ.text("VERI_SIGNE") == "OUI");
  }
  if (option == "APPUI") {
    const auto nodes = unionOf(nodeGroups(m, occ, "GROUP_NO"));
    std::vector<bool> in(static_cast<std::size_t>(m.nodeCount()), false);
    for (const NodeId n : nodes) {
      in[static_cast<std::size_t>(n)] = true;
    }
    return cellsByNodes(
        m, all, [&](NodeId n) { return in[static_cast<std::size_t>(n)]; },
        criterionOf(occ.text("TYPE_APPUI")));
  }
  const Point3 centre = centreOf(m, occ);
  if (option == "SPHERE" || option == "CYLINDRE" || option == "BANDE") { // the options with CRIT_NOEUD
    return cellsAround(m, occ, option, centre);
  }
  fail("DEFI_GROUP_4", {{"option", option}}, occ.locationOf("OPTION"));
}

std::vector<CellId> creaGroupMaCells(const Mesh& m, const KeywordTree& occ) {
  std::vector<CellId> cells;
  if (occ.has("TOUT")) {
    cells = allCells(m);
  } else if (occ.has("GROUP_MA")) {
    cells = cellGroup(m, occ.text("GROUP_MA"), occ.locationOf("GROUP_MA"));
  } else if (occ.has("MAILLE")) {
    for (const auto& n : occ.texts("MAILLE")) {
      const auto c = m.findCell(n);
      if (!c) {
        fail("DEFI_GROUP_2.2", {{"n", n}}, occ.locationOf("MAILLE"));
      }
      cells.push_back(*c);
    }
  } else if (occ.has("UNION")) {
    cells = unionOf(cellGroups(m, occ, "UNION"));
  } else if (occ.has("INTERSEC")) {
    cells = intersectionOf(cellGroups(m, occ, "INTERSEC"));
  } else if (occ.has("DIFFE")) {
    cells = differenceOf(cellGroups(m, occ, "DIFFE"));
  } else if (occ.has("OPTION")) {
    cells = optionCells(m, occ);
  }
  return filterCellType(m, cells, occ.text("TYPE_MAILLE"));
}

// INTERVALLE_VALE: the values of component NOM_CMP at every node (nullopt where it is not
// defined), from the nodal field of a result's step, or the coordinates X, Y, Z.
std::vector<std::optional<double>> nodalValues(const Mesh& m, const KeywordTree& occ) {
  const std::string cmp = occ.text("NOM_CMP");
  std::vector<std::optional<double>> v(static_cast<std::size_t>(m.nodeCount()));
  if (occ.has("CHAM_GD")) {
    fail("DEFI_GROUP_4.2", {}, occ.locationOf("CHAM_GD"));
  }
  if (!occ.has("RESULTAT")) {
    const std::map<std::string, std::size_t> axes{{"X", 0}, {"Y", 1}, {"Z", 2}};
    const auto it = axes.find(cmp);
    if (it == axes.end()) {
      fail("DEFI_GROUP_9", {}, occ.locationOf("NOM_CMP"));
    }
    for (NodeId n = 0; n < m.nodeCount(); ++n) {
      v[static_cast<std::size_t>(n)] = m.point(n)[it->second];
    }
    return v;
  }
  const auto c = occ.conceptValue("RESULTAT");
  const auto result = conceptData<Result>(c);
  STELLA_ASSERT(result != nullptr, "RESULTAT holds no result");
  const ResultStep* step = &selectStep(*result, c->name, occ, occ.real("PRECISION"));
  const std::string name = occ.text("NOM_CHAM");
  const Field* f = step->field(name);
  if (f == nullptr || f->support() != FieldSupport::Node) {
    fail("DEFI_GROUP_9.2", {{"name", c->name}, {"name_2", name}, {"number", step->number}}, occ.location());
  }
  const auto k = f->componentIndex(cmp);
  if (!k) {
    std::string known;
    for (const auto& x : f->components()) {
      known += (known.empty() ? "" : ", ") + x;
    }
    fail("DEFI_GROUP_9.3", {{"name", name}, {"cmp", cmp}, {"known", known}}, occ.locationOf("NOM_CMP"));
  }
  for (std::size_t n = 0; n < v.size() && n < f->entityCount(); ++n) {
    if (!f->partial() || f->defined(n, *k)) {
      v[n] = f->value(n, *k);
    }
  }
  return v;
}

// TUNNEL: the nodes of the cells (TOUT, GROUP_MA) within RAYON of the axis GROUP_MA_AXE (a chain of
// segments walked from GROUP_NO_ORIG), over the first LONGUEUR of the axis (all of it by
// default). A node is inside when its projection on some axis segment falls within the segment
// (before the LONGUEUR cut) and its distance to the segment's line is at most RAYON, or when it is
// within RAYON of an inner vertex of the axis on the outer side of the bend (so that bends leave
// no gap).
std::vector<NodeId> tunnelNodes(const Mesh& m, const KeywordTree& occ) {
  if (!occ.has("GROUP_MA_AXE") || !occ.has("GROUP_NO_ORIG")) {
    fail("DEFI_GROUP_3.3", {}, occ.location());
  }
  if (occ.has("MAILLE")) {
    fail("DEFI_GROUP_4.3", {}, occ.locationOf("MAILLE"));
  }
  const auto origin = nodeGroup(m, occ.text("GROUP_NO_ORIG"), occ.locationOf("GROUP_NO_ORIG"));
  if (origin.size() != 1) {
    fail("DEFI_GROUP_3.4", {}, occ.locationOf("GROUP_NO_ORIG"));
  }
  const auto axis =
      orderedChainNodes(m, unionOf(cellGroups(m, occ, "GROUP_MA_AXE")), origin.front(), std::nullopt);
  // The axis polyline cut at LONGUEUR.
  std::vector<Point3> line{m.point(axis.front())};
  double remaining = occ.has("LONGUEUR") ? occ.real("LONGUEUR") : std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < axis.size() && remaining > 0.0; ++i) {
    const Point3 a = line.back();
    const Point3 b = m.point(axis[i]);
    const double length = norm(b - a);
    if (length <= remaining) {
      line.push_back(b);
      remaining -= length;
    } else {
      line.push_back(a + (remaining / length) * (b - a));
      remaining = 0.0;
    }
  }
  const double r = occ.real("RAYON");
  // Parameter of the projection of x on segment i (0 at its start, 1 at its end).
  const auto along = [&](const Point3& x, std::size_t i) {
    const Point3 d = line[i + 1] - line[i];
    const double l2 = dot(d, d);
    return l2 > 0.0 ? dot(x - line[i], d) / l2 : -1.0;
  };
  const auto inside = [&](const Point3& x) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const double s = along(x, i);
      if (s >= 0.0 && s <= 1.0 && norm(x - (line[i] + s * (line[i + 1] - line[i]))) <= r) {
        return true;
      }
      // The wedge outside a bend at inner vertex i: past the previous segment, before this one.
      if (i > 0 && norm(x - line[i]) <= r && along(x, i - 1) > 1.0 && s < 0.0) {
        return true;
      }
    }
    return false;
  };
  const auto cells = occ.has("TOUT") ? allCells(m) : unionOf(cellGroups(m, occ, "GROUP_MA"));
  std::vector<NodeId> out;
  for (const NodeId n : nodesOfCells(m, cells, "TOUS")) {
    if (inside(m.point(n))) {
      out.push_back(n);
    }
  }
  return out;
}

void creaGroupNo(Mesh& m, const KeywordTree& occ, std::vector<std::string>& made) {
  const auto setGroup = [&](const std::string& name, std::vector<NodeId> nodes, bool ordered) {
    if (ordered) {
      m.setOrderedNodeGroup(name, std::move(nodes));
    } else {
      m.setNodeGroup(name, std::move(nodes));
    }
    made.push_back(name);
  };
  if (!occ.has("OPTION")) {
    if (occ.has("TOUT_GROUP_MA")) {
      const auto groups = m.cellGroups();
      for (const auto& [g, cells] : groups) {
        setGroup(g, nodesOfCells(m, cells, "TOUS"), false); // no CRIT_NOEUD with TOUT_GROUP_MA
      }
      return;
    }
    if (occ.has("GROUP_MA")) {
      const auto groups = occ.texts("GROUP_MA");
      const auto names = occ.has("NOM") ? occ.texts("NOM") : groups;
      if (names.size() != groups.size()) {
        fail("DEFI_GROUP_3.5", {}, occ.locationOf("NOM"));
      }
      for (std::size_t i = 0; i < groups.size(); ++i) {
        setGroup(names[i],
                 nodesOfCells(m, cellGroup(m, groups[i], occ.locationOf("GROUP_MA")), occ.text("CRIT_NOEUD")),
                 false);
      }
      return;
    }
    std::vector<NodeId> nodes;
    if (occ.has("GROUP_NO")) {
      nodes = unionOf(nodeGroups(m, occ, "GROUP_NO"));
    } else if (occ.has("NOEUD")) {
      for (const auto& n : occ.texts("NOEUD")) {
        const auto id = m.findNode(n);
        if (!id) {
          fail("DEFI_GROUP_2.3", {{"n", n}}, occ.locationOf("NOEUD"));
        }
        nodes.push_back(*id);
      }
      setGroup(occ.text("NOM"), nodes, true); // NOEUD keeps the user's order
      return;
    } else if (occ.has("UNION")) {
      nodes = unionOf(nodeGroups(m, occ, "UNION"));
    } else if (occ.has("INTERSEC")) {
      nodes = intersectionOf(nodeGroups(m, occ, "INTERSEC"));
    } else if (occ.has("DIFFE")) {
      nodes = differenceOf(nodeGroups(m, occ, "DIFFE"));
    }
    setGroup(occ.text("NOM"), nodes, false);
    return;
  }
  const std::string option = occ.text("OPTION");
  const std::string name = occ.text("NOM");
  // PRECISION: ENV_SPHERE, ENV_CYLINDRE, PLAN and SEGM_DROI_ORDO only
  const auto precisionOf = [&occ] { return occ.real("PRECISION"); };
  if (option == "ENV_SPHERE") {
    const double precision = precisionOf();
    const Point3 c = centreOf(m, occ);
    const double r = occ.real("RAYON");
    setGroup(name, nodesWhere(m, [&](const Point3& x) { return std::abs(norm(x - c) - r) <= precision; }),
             false);
  } else if (option == "ENV_CYLINDRE") {
    const double precision = precisionOf();
    const Point3 c = centreOf(m, occ);
    const Point3 axis = directionOf(occ);
    const double r = occ.real("RAYON");
    setGroup(
        name,
        nodesWhere(m, [&](const Point3& x) { return std::abs(distanceToAxis(x, c, axis) - r) <= precision; }),
        false);
  } else if (option == "PLAN") {
    const double precision = precisionOf();
    const Point3 c = centreOf(m, occ);
    const Point3 normal = directionOf(occ);
    setGroup(name, nodesWhere(m, [&](const Point3& x) { return distanceToPlane(x, c, normal) <= precision; }),
             false);
  } else if (option == "NOEUD_ORDO") {
    const auto cells = unionOf(cellGroups(m, occ, "GROUP_MA"));
    const auto single = [&](const char* kw) -> std::optional<NodeId> {
      if (!occ.has(kw)) {
        return std::nullopt;
      }
      const auto nodes = nodeGroup(m, occ.text(kw), occ.locationOf(kw));
      if (nodes.size() != 1) {
        fail("DEFI_GROUP_3.6", {{"kw", std::string(kw)}}, occ.locationOf(kw));
      }
      return nodes.front();
    };
    setGroup(name, orderedChainNodes(m, cells, single("GROUP_NO_ORIG"), single("GROUP_NO_EXTR")), true);
  } else if (option == "SEGM_DROI_ORDO") {
    const auto a = nodeGroup(m, occ.text("GROUP_NO_ORIG"), occ.locationOf("GROUP_NO_ORIG"));
    const auto b = nodeGroup(m, occ.text("GROUP_NO_EXTR"), occ.locationOf("GROUP_NO_EXTR"));
    if (a.size() != 1 || b.size() != 1) {
      fail("DEFI_GROUP_3.7", {}, occ.location());
    }
    std::vector<NodeId> candidates;
    if (occ.has("GROUP_NO")) {
      candidates = unionOf(nodeGroups(m, occ, "GROUP_NO"));
    } else {
      candidates.resize(static_cast<std::size_t>(m.nodeCount()));
      std::iota(candidates.begin(), candidates.end(), 0);
    }
    setGroup(
        name,
        nodesOnSegment(m, candidates, a.front(), b.front(), precisionOf(), occ.text("CRITERE") == "RELATIF"),
        true);
  } else if (option == "INTERVALLE_VALE") {
    const auto bounds = occ.reals("VALE");
    const auto values = nodalValues(m, occ);
    std::vector<NodeId> nodes;
    for (std::size_t n = 0; n < values.size(); ++n) {
      if (values[n] && *values[n] >= bounds[0] && *values[n] <= bounds[1]) {
        nodes.push_back(static_cast<NodeId>(n));
      }
    }
    setGroup(name, nodes, false);
  } else if (option == "TUNNEL") {
    setGroup(name, tunnelNodes(m, occ), false);
  } else {
    fail("DEFI_GROUP_4.4", {{"option", option}}, occ.locationOf("OPTION"));
  }
}

Value runDefiGroup(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  if (!kw.has("MAILLAGE")) {
    fail("DEFI_GROUP_4.5", {}, call.location);
  }
  auto data = conceptData<MeshConcept>(kw.conceptValue("MAILLAGE"));
  STELLA_ASSERT(data != nullptr && data->mesh != nullptr, "MAILLAGE holds no mesh");
  Mesh& m = *data->mesh;
  const bool alarm = kw.text("ALARME") == "OUI";
  for (const auto& occ : kw.occurrences("DETR_GROUP_MA")) {
    for (const auto& g : occ.texts("NOM")) {
      if (!m.removeCellGroup(g) && alarm) {
        call.session.report(msg::make("DEFI_GROUP_6", {{"g", g}}, occ.locationOf("NOM")));
      }
    }
  }
  for (const auto& occ : kw.occurrences("DETR_GROUP_NO")) {
    for (const auto& g : occ.texts("NOM")) {
      if (!m.removeNodeGroup(g) && alarm) {
        call.session.report(msg::make("DEFI_GROUP_6.2", {{"g", g}}, occ.locationOf("NOM")));
      }
    }
  }
  for (const auto& occ : kw.occurrences("CREA_GROUP_MA")) {
    const std::string name = occ.text("NOM");
    if (m.hasCellGroup(name)) {
      fail("DEFI_GROUP_7", {{"name", name}}, occ.locationOf("NOM"));
    }
    auto cells = creaGroupMaCells(m, occ);
    if (cells.empty() && alarm) {
      call.session.report(msg::make("DEFI_GROUP_8", {{"name", name}}, occ.location()));
    }
    call.session.message() << fmt::format("   DEFI_GROUP: group of cells {} ({} cells)\n", name,
                                          cells.size());
    m.setCellGroup(name, std::move(cells));
  }
  for (const auto& occ : kw.occurrences("CREA_GROUP_NO")) {
    std::vector<std::string> made;
    creaGroupNo(m, occ, made);
    for (const auto& g : made) {
      const std::size_t n = m.nodeGroup(g)->size();
      if (n == 0 && alarm) {
        call.session.report(msg::make("DEFI_GROUP_8.2", {{"g", g}}, occ.location()));
      }
      call.session.message() << fmt::format("   DEFI_GROUP: group of nodes {} ({} nodes)\n", g, n);
    }
  }
  return call.makeConcept(data);
}

} // namespace

STELLA_OPERATOR("DEFI_GROUP", runDefiGroup);

} // namespace stella
