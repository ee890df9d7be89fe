// CREA_MAILLAGE: a new mesh from MAILLAGE by one operation: LINE_QUAD, QUAD_LINE, HEXA20_27,
// PENTA15_18, MODI_MAILLE (QUAD8_9, TRIA6_7, SEG3_4), CREA_POI1, RESTREINT, DECOUPE_LAC (the
// patches of LAC contact, solver/mesh/LacCutting.hpp). Others are refused as not implemented yet.

#include "messages/Messages.hpp"
#include "solver/mesh/GroupOperations.hpp"
#include "solver/mesh/LacCutting.hpp"
#include "solver/mesh/MeshConversion.hpp"
#include "solver/mesh/MeshSummary.hpp"
#include "solver/operators/MeshOperatorUtil.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

namespace stella {

namespace {

std::vector<CellId> selection(const Mesh& mesh, const KeywordTree& occ) {
  return occ.has("GROUP_MA") ? cellsOfGroups(mesh, occ, "GROUP_MA") : std::vector<CellId>{};
}

// DECOUPE_LAC: GROUP_MA_ESCL (each group a contact zone), DECOUPE_HEXA.
Mesh decoupeLac(const Mesh& mesh, const KeywordTree& occ, std::ostream& message) {
  const auto groups = occ.texts("GROUP_MA_ESCL");
  cellsOfGroups(mesh, occ, "GROUP_MA_ESCL"); // MESHOP_1 for a missing group
  const LacHexaCut mode = occ.text("DECOUPE_HEXA") == "HEXA" ? LacHexaCut::Hexahedra : LacHexaCut::Pyramids;
  LacCuttingReport report;
  Mesh out = cutMeshForLac(mesh, groups, mode, occ.locationOf("GROUP_MA_ESCL"), &report);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    message << "DECOUPE_LAC: slave group " << g + 1 << " (" << groups[g]
            << "): " << report.slaveCellsPerGroup[g] << " cells\n";
  }
  message << "DECOUPE_LAC: " << report.cutCells << " cells cut, " << out.nodeCount() - mesh.nodeCount()
          << " nodes and " << out.cellCount() - mesh.cellCount() << " cells added\n";
  return out;
}

Mesh apply(const Mesh& mesh, const KeywordTree& kw, std::ostream& message) {
  const std::pair<const char*, CellConversion> simple[] = {{"LINE_QUAD", CellConversion::LineToQuad},
                                                           {"QUAD_LINE", CellConversion::QuadToLine},
                                                           {"HEXA20_27", CellConversion::Hexa20To27},
                                                           {"PENTA15_18", CellConversion::Penta15To18}};
  for (const auto& [key, conversion] : simple) {
    if (kw.has(key)) {
      return convertCells(mesh, conversion, selection(mesh, kw.occurrences(key).front()));
    }
  }
  if (kw.has("MODI_MAILLE")) {
    Mesh out = mesh;
    for (const auto& occ : kw.occurrences("MODI_MAILLE")) {
      const std::string option = occ.text("OPTION");
      const CellConversion c = option == "QUAD8_9"   ? CellConversion::Quad8To9
                               : option == "TRIA6_7" ? CellConversion::Tria6To7
                               : option == "SEG3_4"  ? CellConversion::Seg3To4
                                                     : CellConversion::LineToQuad;
      if (option == "QUAD_TRIA3") {
        throw UserError(msg::make("CREA_MAILLAGE_1", {}, occ.locationOf("OPTION")));
      }
      out = convertCells(out, c, selection(out, occ));
    }
    return out;
  }
  if (kw.has("CREA_POI1")) {
    Mesh out = mesh;
    for (const auto& occ : kw.occurrences("CREA_POI1")) {
      std::vector<NodeId> nodes;
      if (occ.has("TOUT")) {
        for (NodeId n = 0; n < out.nodeCount(); ++n) {
          nodes.push_back(n);
        }
      }
      if (occ.has("GROUP_MA")) {
        const auto more = out.nodesOfCells(cellsOfGroups(out, occ, "GROUP_MA"));
        nodes.insert(nodes.end(), more.begin(), more.end());
      }
      if (occ.has("GROUP_NO")) {
        const auto more = nodesOfGroups(out, occ, "GROUP_NO");
        nodes.insert(nodes.end(), more.begin(), more.end());
      }
      nodes = unionOf({nodes});
      out = addPointCells(out, nodes, occ.has("NOM_GROUP_MA") ? occ.texts("NOM_GROUP_MA").front() : "");
    }
    return out;
  }
  if (kw.has("DECOUPE_LAC")) {
    return decoupeLac(mesh, kw.occurrences("DECOUPE_LAC").front(), message);
  }
  if (kw.has("RESTREINT")) {
    const auto& occ = kw.occurrences("RESTREINT").front();
    auto cellGroups = occ.texts("GROUP_MA");
    std::vector<std::string> nodeGroups =
        occ.has("GROUP_NO") ? occ.texts("GROUP_NO") : std::vector<std::string>{};
    if (occ.text("TOUT_GROUP_MA") == "OUI") {
      cellGroups.clear();
      for (const auto& [g, ids] : mesh.cellGroups()) {
        cellGroups.push_back(g);
      }
    }
    if (occ.text("TOUT_GROUP_NO") == "OUI") {
      nodeGroups.clear();
      for (const auto& [g, ids] : mesh.nodeGroups()) {
        nodeGroups.push_back(g);
      }
    }
    return restrictMesh(mesh, cellsOfGroups(mesh, occ, "GROUP_MA"), cellGroups, nodeGroups);
  }
  for (const auto& k : kw.factors()) {
    if (!k.occurrences.empty()) {
      throw UserError(msg::make("CREA_MAILLAGE_1.2", {{"name", k.name}}, k.location));
    }
  }
  throw UserError(msg::make("CREA_MAILLAGE_1.3", {}, kw.location()));
}

Value runCreaMaillage(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  auto source = meshConceptOf(kw);
  auto mesh = std::make_shared<Mesh>(apply(*source->mesh, kw, call.session.message()));
  mesh->setName(call.resultName);
  call.session.message() << meshSummary(*mesh, call.resultName, kw.integer("INFO") >= 2);
  return call.makeConcept(std::make_shared<MeshConcept>(mesh));
}

} // namespace

STELLA_OPERATOR("CREA_MAILLAGE", runCreaMaillage);

} // namespace stella
