#pragma once
// Helpers shared by the mesh operators (LIRE_MAILLAGE, DEFI_GROUP, MODI_MAILLAGE, CREA_MAILLAGE,
// MACR_INFO_MAIL, IMPR_RESU): the mesh of a MAILLAGE keyword and group lookups that raise
// UserError MESHOP_1 naming the missing group and listing the existing ones.

#include "catalog/KeywordTree.hpp"
#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/MeshConcept.hpp"

#include <string>
#include <vector>

namespace stella {

inline std::shared_ptr<MeshConcept> meshConceptOf(const KeywordTree& kw,
                                                  const std::string& name = "MAILLAGE") {
  auto data = conceptData<MeshConcept>(kw.conceptValue(name));
  STELLA_ASSERT(data != nullptr && data->mesh != nullptr, name + " holds no mesh");
  return data;
}

// Union of the cell groups named by keyword `key` of `occ` (sorted).
inline std::vector<CellId> cellsOfGroups(const Mesh& mesh, const KeywordTree& occ, const std::string& key) {
  std::vector<CellId> out;
  for (const auto& g : occ.texts(key)) {
    const auto* ids = mesh.cellGroup(g);
    if (ids == nullptr) {
      std::string known;
      for (const auto& [n, v] : mesh.cellGroups()) {
        known += (known.empty() ? "" : ", ") + n;
      }
      throw UserError(msg::make("MESHOP_1", {{"g", g}}, occ.locationOf(key))
                          .withNote(msg::text("MESHOP_1.n2",
                                              {{"value", (known.empty() ? std::string("(none)") : known)}})));
    }
    out.insert(out.end(), ids->begin(), ids->end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

inline std::vector<NodeId> nodesOfGroups(const Mesh& mesh, const KeywordTree& occ, const std::string& key) {
  std::vector<NodeId> out;
  for (const auto& g : occ.texts(key)) {
    const auto* ids = mesh.nodeGroup(g);
    if (ids == nullptr) {
      std::string known;
      for (const auto& [n, v] : mesh.nodeGroups()) {
        known += (known.empty() ? "" : ", ") + n;
      }
      throw UserError(msg::make("MESHOP_1.2", {{"g", g}}, occ.locationOf(key))
                          .withNote(msg::text("MESHOP_1.n1",
                                              {{"value", (known.empty() ? std::string("(none)") : known)}})));
    }
    out.insert(out.end(), ids->begin(), ids->end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

} // namespace stella
