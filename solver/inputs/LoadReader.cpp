// AFFE_CHAR_MECA / AFFE_CHAR_CINE keywords -> MechanicalLoad / KinematicLoad.

#include "solver/inputs/LoadReader.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/inputs/Selection.hpp"
#include "solver/model/RigidRelations.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

const char* const physicalDofs[] = {"DX", "DY", "DZ"};
const char* const otherDofs[] = {"DRX",     "DRY",     "DRZ",  "GRX",   "PRES", "PHI",
                                 "TEMP",    "PRE1",    "PRE2", "GONF",  "GLIS", "LAGS_C",
                                 "LAGS_F1", "LAGS_F2", "DNOR", "DRNOR", "DTAN"};

UserError missingComponent(const Model& model, const std::string& name, const SourceLocation& at) {
  return UserError(msg::make("LOAD_1",
                             {{"name", name},
                              {"join", fmt::join(model.componentNames(), ", ")},
                              {"name_2", name == "DZ" ? " (a 2D model has no DZ)" : ""}},
                             at));
}

int componentOrThrow(const Model& model, const std::string& name, const SourceLocation& at) {
  auto c = model.componentIndex(name);
  if (!c) {
    throw missingComponent(model, name, at);
  }
  return *c;
}

std::vector<CellId> cellsOfKind(const Model& model, const KeywordTree& occ, ElementKind kind,
                                const char* keyword) {
  std::vector<CellId> out;
  for (CellId c : selectCells(*model.mesh, occ)) {
    if (model.cell(c).kind == kind) {
      out.push_back(c);
    }
  }
  if (out.empty()) {
    const char* what = kind == ElementKind::Skin
                           ? (model.components == 2 ? "edge (SEG) cells" : "face (TRIA, QUAD) cells")
                           : "volume cells";
    throw UserError(
        msg::make("LOAD_3", {{"keyword", keyword}, {"what", what}}, occ.location())
            .withNote(msg::text(
                "LOAD_3.n3",
                {{"kind", std::string(kind == ElementKind::Skin ? "skin elements" : "volume elements")}})));
  }
  return out;
}

std::array<double, 3> forceVector(const Model& model, const KeywordTree& occ) {
  std::array<double, 3> f{};
  for (int c = 0; c < 3; ++c) {
    const std::string name = std::string("F") + "XYZ"[c];
    if (occ.has(name)) {
      if (c >= model.components) {
        throw missingComponent(model, "D" + name.substr(1), occ.locationOf(name));
      }
      f[static_cast<std::size_t>(c)] = occ.real(name);
    }
  }
  return f;
}

void readImposed(const Model& model, const KeywordTree& occ, const char* keyword, MechanicalLoad& load) {
  if (occ.has("BLOCAGE")) {
    throw UserError(msg::make("LOAD_4.2", {}, occ.locationOf("BLOCAGE")));
  }
  const auto components = imposedComponents(model, occ);
  for (NodeId n : modelNodes(model, occ)) {
    for (const auto& [c, v] : components) {
      load.relations.push_back({{{n, c, 1.0}}, v, keyword});
    }
  }
}

void readLiaisonDdl(const Model& model, const KeywordTree& occ, MechanicalLoad& load) {
  std::vector<NodeId> nodes;
  if (occ.has("NOEUD")) {
    for (const auto& name : occ.texts("NOEUD")) {
      nodes.push_back(nodeOrThrow(*model.mesh, name, occ, "NOEUD"));
    }
  } else {
    for (const auto& g : occ.texts("GROUP_NO")) { // each group names one node, in order
      const auto& group = nodeGroupOrThrow(*model.mesh, g, occ, "GROUP_NO");
      nodes.insert(nodes.end(), group.begin(), group.end());
    }
  }
  const auto dofs = occ.texts("DDL");
  const auto coefs = occ.reals("COEF_MULT");
  if (nodes.size() != dofs.size() || nodes.size() != coefs.size()) {
    throw UserError(msg::make(
        "LOAD_5", {{"nodes_count", nodes.size()}, {"dofs_count", dofs.size()}, {"coefs_count", coefs.size()}},
        occ.location()));
  }
  LinearRelation r;
  r.value = occ.real("COEF_IMPO");
  r.origin = "LIAISON_DDL";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!model.nodeActive(nodes[i])) {
      throw UserError(msg::make("LOAD_2", {{"node_name", model.mesh->nodeName(nodes[i])}}, occ.location()));
    }
    r.terms.push_back({nodes[i], componentOrThrow(model, dofs[i], occ.locationOf("DDL")), coefs[i]});
  }
  load.relations.push_back(std::move(r));
}

void readLiaisonUnif(const Model& model, const KeywordTree& occ, MechanicalLoad& load) {
  const auto nodes = modelNodes(model, occ);
  for (const auto& name : occ.texts("DDL")) {
    const int c = componentOrThrow(model, name, occ.locationOf("DDL"));
    for (std::size_t i = 1; i < nodes.size(); ++i) {
      load.relations.push_back({{{nodes[0], c, 1.0}, {nodes[i], c, -1.0}}, 0.0, "LIAISON_UNIF"});
    }
  }
}

void readLiaisonSolide(const Model& model, const KeywordTree& occ, MechanicalLoad& load) {
  const auto nodes = modelNodes(model, occ);
  auto relations = rigidBodyRelations(*model.mesh, nodes, model.components, occ.realOr("DIST_MIN", 0.0));
  for (auto& r : relations) {
    load.relations.push_back(std::move(r));
  }
}

void readForces(const Model& model, const KeywordTree& keywords, MechanicalLoad& load) {
  for (const KeywordTree& occ : keywords.occurrences("FORCE_NODALE")) {
    for (const char* m : {"MX", "MY", "MZ", "ANGL_NAUT"}) {
      if (occ.has(m)) {
        throw UserError(msg::make("LOAD_4.3", {{"m", m}}, occ.locationOf(m)));
      }
    }
    const auto f = forceVector(model, occ);
    for (NodeId n : modelNodes(model, occ)) {
      for (int c = 0; c < model.components; ++c) {
        if (f[static_cast<std::size_t>(c)] != 0.0) {
          load.nodalForces.push_back({n, c, f[static_cast<std::size_t>(c)]});
        }
      }
    }
  }
  for (const KeywordTree& occ : keywords.occurrences("PRES_REP")) {
    if (occ.has("CISA_2D")) {
      throw UserError(msg::make("LOAD_4.4", {}, occ.locationOf("CISA_2D")));
    }
    for (CellId c : cellsOfKind(model, occ, ElementKind::Skin, "PRES_REP")) {
      load.pressures.push_back({c, occ.real("PRES")});
    }
  }
  for (const char* key : {"FORCE_CONTOUR", "FORCE_FACE"}) {
    for (const KeywordTree& occ : keywords.occurrences(key)) {
      const bool twoD = std::string(key) == "FORCE_CONTOUR";
      if (twoD != (model.components == 2)) {
        throw UserError(msg::make("LOAD_3.2", {{"key", key}, {"two_d", twoD ? "2D" : "3D"}}, occ.location())
                            .withNote(twoD ? msg::text("LOAD_3.n1") : msg::text("LOAD_3.n2")));
      }
      const auto f = forceVector(model, occ);
      for (CellId c : cellsOfKind(model, occ, ElementKind::Skin, key)) {
        load.surfaceForces.push_back({c, f});
      }
    }
  }
  for (const KeywordTree& occ : keywords.occurrences("FORCE_INTERNE")) {
    const auto f = forceVector(model, occ);
    for (CellId c : cellsOfKind(model, occ, ElementKind::Volume, "FORCE_INTERNE")) {
      load.volumeForces.push_back({c, f});
    }
  }
  for (const KeywordTree& occ : keywords.occurrences("PESANTEUR")) {
    auto d = occ.reals("DIRECTION");
    const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (!(norm > 0.0)) {
      throw UserError(msg::make("LOAD_6", {}, occ.locationOf("DIRECTION")));
    }
    Gravity g;
    const double a = occ.real("GRAVITE") / norm;
    g.acceleration = {a * d[0], a * d[1], a * d[2]};
    if (occ.has("GROUP_MA")) {
      g.cells = cellsOfKind(model, occ, ElementKind::Volume, "PESANTEUR");
    } else {
      g.cells = model.cellsOfKind(ElementKind::Volume);
    }
    load.gravity.push_back(std::move(g));
  }
}

} // namespace

std::vector<std::pair<int, double>> imposedComponents(const Model& model, const KeywordTree& occ) {
  std::vector<std::pair<int, double>> out;
  for (const char* name : otherDofs) {
    if (occ.has(name)) {
      throw UserError(msg::make("LOAD_1.2",
                                {{"name", name}, {"join", fmt::join(model.componentNames(), ", ")}},
                                occ.locationOf(name)));
    }
  }
  for (const char* name : physicalDofs) {
    if (occ.has(name)) {
      out.emplace_back(componentOrThrow(model, name, occ.locationOf(name)), occ.real(name));
    }
  }
  return out;
}

std::vector<NodeId> modelNodes(const Model& model, const KeywordTree& occ) {
  auto nodes = selectNodes(*model.mesh, occ);
  for (NodeId n : nodes) {
    if (!model.nodeActive(n)) {
      throw UserError(msg::make("LOAD_2.2", {{"node_name", model.mesh->nodeName(n)}}, occ.location()));
    }
  }
  if (nodes.empty()) {
    throw UserError(msg::make("LOAD_2.3", {}, occ.location()));
  }
  return nodes;
}

void readMechanicalLoad(const KeywordTree& keywords, MechanicalLoad& load) {
  const Model& model = *load.model;
  for (const char* key : {"ROTATION", "ARETE_IMPO", "LIAISON_OBLIQUE", "LIAISON_GROUP", "LIAISON_MAIL",
                          "FORCE_ARETE", "FORCE_POUTRE", "FORCE_COQUE", "PRE_SIGM", "PRE_EPSI"}) {
    if (keywords.has(key)) {
      throw UserError(msg::make("LOAD_4.5", {{"key", key}}, keywords.locationOf(key)));
    }
  }
  for (const KeywordTree& occ : keywords.occurrences("DDL_IMPO")) {
    readImposed(model, occ, "DDL_IMPO", load);
  }
  for (const KeywordTree& occ : keywords.occurrences("FACE_IMPO")) {
    readImposed(model, occ, "FACE_IMPO", load);
  }
  for (const KeywordTree& occ : keywords.occurrences("LIAISON_DDL")) {
    readLiaisonDdl(model, occ, load);
  }
  for (const KeywordTree& occ : keywords.occurrences("LIAISON_UNIF")) {
    readLiaisonUnif(model, occ, load);
  }
  for (const KeywordTree& occ : keywords.occurrences("LIAISON_SOLIDE")) {
    readLiaisonSolide(model, occ, load);
  }
  readForces(model, keywords, load);
}

void readKinematicLoad(const KeywordTree& keywords, KinematicLoad& load) {
  if (keywords.has("EVOL_IMPO")) {
    throw UserError(msg::make("LOAD_4.6", {}, keywords.locationOf("EVOL_IMPO")));
  }
  for (const KeywordTree& occ : keywords.occurrences("MECA_IMPO")) {
    const auto components = imposedComponents(*load.model, occ);
    for (NodeId n : modelNodes(*load.model, occ)) {
      for (const auto& [c, v] : components) {
        load.imposed.push_back({n, c, v});
      }
    }
  }
}

} // namespace stella
