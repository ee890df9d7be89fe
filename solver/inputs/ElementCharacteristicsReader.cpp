// AFFE_CARA_ELEM keywords -> ElementCharacteristics (discrete spring stiffnesses).

#include "solver/inputs/ElementCharacteristicsReader.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/Selection.hpp"
#include "solver/model/Model.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <map>

namespace stella {

namespace {

const char* const refusedFactors[] = {"POUTRE", "BARRE",    "COQUE",  "CABLE",
                                      "MASSIF", "MEMBRANE", "GRILLE", "ORIENTATION"};

void refuseUnimplemented(const KeywordTree& keywords) {
  for (const char* key : refusedFactors) {
    if (keywords.has(key)) {
      throw UserError(Diagnostic::fatal("CARA_1",
                                        fmt::format("AFFE_CARA_ELEM {} is not implemented yet", key),
                                        keywords.locationOf(key))
                          .withNote("implemented: DISCRET and DISCRET_2D with CARA='K_T_D_N' (springs on "
                                    "POI1 cells carrying 'DIS_T' / '2D_DIS_T')"));
    }
  }
}

// The discrete cells of the model that an occurrence designates (GROUP_MA: its POI1 cells;
// GROUP_NO: the discrete cells on its nodes).
std::vector<CellId> discreteCells(const Model& model, const KeywordTree& occ) {
  const Mesh& mesh = *model.mesh;
  std::vector<CellId> out;
  if (occ.has("GROUP_NO")) {
    const auto nodes = selectNodes(mesh, occ);
    for (CellId c : model.cellsOfKind(ElementKind::Discrete)) {
      if (std::binary_search(nodes.begin(), nodes.end(), mesh.cellNodes(c)[0])) {
        out.push_back(c);
      }
    }
    return out;
  }
  for (CellId c : selectCells(mesh, occ)) {
    if (model.cell(c).kind == ElementKind::Discrete) {
      out.push_back(c);
    }
  }
  return out;
}

std::array<double, 3> stiffnessOf(const KeywordTree& occ, const std::string& keyword, int components) {
  const std::string cara = occ.text("CARA");
  if (cara != "K_T_D_N") {
    throw UserError(Diagnostic::fatal("CARA_1",
                                      fmt::format("{} CARA='{}' is not implemented yet", keyword, cara),
                                      occ.locationOf("CARA"))
                        .withNote("implemented: CARA='K_T_D_N' (diagonal translational stiffness of a "
                                  "spring on a POI1 cell)"));
  }
  if (occ.has("AMOR_HYST")) {
    throw UserError(Diagnostic::fatal("CARA_1", fmt::format("{} AMOR_HYST is not implemented yet", keyword),
                                      occ.locationOf("AMOR_HYST")));
  }
  const auto vale = occ.reals("VALE");
  if (static_cast<int>(vale.size()) != components) {
    throw UserError(Diagnostic::fatal("CARA_2",
                                      fmt::format("{} CARA='K_T_D_N' needs {} values in VALE, got {}",
                                                  keyword, components, vale.size()),
                                      occ.locationOf("VALE"))
                        .withNote(components == 3 ? "VALE=(KX, KY, KZ)" : "VALE=(KX, KY)"));
  }
  std::array<double, 3> k{};
  for (int c = 0; c < components; ++c) {
    const double v = vale[static_cast<std::size_t>(c)];
    if (v < 0.0) {
      throw UserError(
          Diagnostic::fatal("CARA_4", fmt::format("{} stiffness K{} = {} is negative", keyword, "XYZ"[c], v),
                            occ.locationOf("VALE"))
              .withNote("a spring stiffness is >= 0"));
    }
    k[static_cast<std::size_t>(c)] = v;
  }
  return k;
}

void readDiscrete(const Model& model, const KeywordTree& keywords, const char* keyword, int components,
                  std::map<CellId, std::array<double, 3>>& stiffness) {
  for (const KeywordTree& occ : keywords.occurrences(keyword)) {
    if (model.components != components) {
      throw UserError(
          Diagnostic::fatal("CARA_3",
                            fmt::format("{} applies to {} models, the model is {}", keyword,
                                        components == 3 ? "3D ('DIS_T')" : "2D ('2D_DIS_T')",
                                        model.components == 3 ? "3D" : "2D"),
                            occ.location())
              .withNote(components == 3 ? "for a 2D model use DISCRET_2D" : "for a 3D model use DISCRET"));
    }
    const auto k = stiffnessOf(occ, keyword, components);
    const auto cells = discreteCells(model, occ);
    if (cells.empty()) {
      throw UserError(
          Diagnostic::fatal("CARA_3",
                            fmt::format("{}: the selection holds no discrete element of the model", keyword),
                            occ.location())
              .withNote(fmt::format("assign MODELISATION='{}' to its POI1 cells in AFFE_MODELE",
                                    components == 3 ? "DIS_T" : "2D_DIS_T")));
    }
    for (CellId c : cells) {
      stiffness[c] = k; // a later occurrence overrides an earlier one, as in code_aster
    }
  }
}

} // namespace

void readElementCharacteristics(const KeywordTree& keywords, ElementCharacteristics& cara) {
  const Model& model = *cara.model;
  refuseUnimplemented(keywords);
  std::map<CellId, std::array<double, 3>> stiffness;
  readDiscrete(model, keywords, "DISCRET", 3, stiffness);
  readDiscrete(model, keywords, "DISCRET_2D", 2, stiffness);
  cara.springs.clear();
  for (const auto& [c, k] : stiffness) {
    cara.springs.push_back({c, model.mesh->cellNodes(c)[0], k});
  }
}

std::shared_ptr<const ElementCharacteristics> readCaraElem(const KeywordTree& keywords) {
  if (!keywords.has("CARA_ELEM")) {
    return nullptr;
  }
  auto cara = conceptData<ElementCharacteristics>(keywords.conceptValue("CARA_ELEM"));
  STELLA_ASSERT(cara != nullptr, "CARA_ELEM holds no element characteristics");
  return cara;
}

} // namespace stella
