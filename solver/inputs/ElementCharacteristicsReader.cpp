// AFFE_CARA_ELEM keywords -> ElementCharacteristics (discrete spring stiffnesses).

#include "solver/inputs/ElementCharacteristicsReader.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
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
      throw UserError(msg::make("CARA_1", {{"key", key}}, keywords.locationOf(key)));
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
    throw UserError(msg::make("CARA_1.2", {{"keyword", keyword}, {"cara", cara}}, occ.locationOf("CARA")));
  }
  if (occ.has("AMOR_HYST")) {
    throw UserError(msg::make("CARA_1.3", {{"keyword", keyword}}, occ.locationOf("AMOR_HYST")));
  }
  const auto vale = occ.reals("VALE");
  if (static_cast<int>(vale.size()) != components) {
    throw UserError(msg::make("CARA_2",
                              {{"keyword", keyword}, {"components", components}, {"vale_count", vale.size()}},
                              occ.locationOf("VALE"))
                        .withNote(components == 3 ? msg::text("CARA_2.n1") : msg::text("CARA_2.n2")));
  }
  std::array<double, 3> k{};
  for (int c = 0; c < components; ++c) {
    const double v = vale[static_cast<std::size_t>(c)];
    if (v < 0.0) {
      throw UserError(
          msg::make("CARA_4", {{"keyword", keyword}, {"value", "XYZ"[c]}, {"v", v}}, occ.locationOf("VALE")));
    }
    k[static_cast<std::size_t>(c)] = v;
  }
  return k;
}

void readDiscrete(const Model& model, const KeywordTree& keywords, const char* keyword, int components,
                  std::map<CellId, std::array<double, 3>>& stiffness) {
  for (const KeywordTree& occ : keywords.occurrences(keyword)) {
    if (model.components != components) {
      throw UserError(msg::make("CARA_3",
                                {{"keyword", keyword},
                                 {"components", components == 3 ? "3D ('DIS_T')" : "2D ('2D_DIS_T')"},
                                 {"components_2", model.components == 3 ? "3D" : "2D"}},
                                occ.location())
                          .withNote(components == 3 ? msg::text("CARA_3.n1") : msg::text("CARA_3.n2")));
    }
    const auto k = stiffnessOf(occ, keyword, components);
    const auto cells = discreteCells(model, occ);
    if (cells.empty()) {
      throw UserError(msg::make(
          "CARA_3.2", {{"keyword", keyword}, {"components", components == 3 ? "DIS_T" : "2D_DIS_T"}},
          occ.location()));
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
