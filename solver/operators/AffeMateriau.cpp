// AFFE_MATERIAU: the material of each cell (AFFE by TOUT or GROUP_MA; a later AFFE overrides an
// earlier one on shared cells). Command variables (AFFE_VARC) are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/MeshConcept.hpp"
#include "solver/inputs/Selection.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/model/Model.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

std::shared_ptr<const Mesh> meshOf(const KeywordTree& kw) {
  if (kw.has("MODELE")) {
    auto model = conceptData<Model>(kw.conceptValue("MODELE"));
    STELLA_ASSERT(model != nullptr, "MODELE holds no model");
    return model->mesh;
  }
  auto mesh = conceptData<MeshConcept>(kw.conceptValue("MAILLAGE"));
  STELLA_ASSERT(mesh != nullptr, "MAILLAGE holds no mesh");
  return mesh->mesh;
}

Value runAffeMateriau(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  for (const char* name : {"AFFE_VARC", "AFFE_COMPOR", "CHAM_MATER"}) {
    if (kw.has(name)) {
      throw UserError(msg::make("MATER_4", {{"name", name}}, kw.locationOf(name)));
    }
  }
  auto field = std::make_shared<MaterialField>();
  field->mesh = meshOf(kw);
  field->cellMaterial.assign(static_cast<std::size_t>(field->mesh->cellCount()), -1);
  for (const KeywordTree& affe : kw.occurrences("AFFE")) {
    auto materials = affe.conceptValues("MATER");
    if (materials.size() != 1) {
      throw UserError(msg::make("MATER_5", {}, affe.locationOf("MATER")));
    }
    auto material = conceptData<Material>(materials.front());
    STELLA_ASSERT(material != nullptr, "MATER holds no material");
    field->materials.push_back(material);
    const int index = static_cast<int>(field->materials.size()) - 1;
    for (CellId c : selectCells(*field->mesh, affe)) {
      field->cellMaterial[static_cast<std::size_t>(c)] = index;
    }
  }
  return call.makeConcept(field);
}

} // namespace

STELLA_OPERATOR("AFFE_MATERIAU", runAffeMateriau);

} // namespace stella
