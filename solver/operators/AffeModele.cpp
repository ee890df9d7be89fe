// AFFE_MODELE: assigns mechanical modelisations to the cells of a mesh (solver/model/ModelBuilder).

#include "interpreter/Diagnostics.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/MeshConcept.hpp"
#include "solver/inputs/Selection.hpp"
#include "solver/model/ModelBuilder.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

Value runAffeModele(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  auto meshData = conceptData<MeshConcept>(kw.conceptValue("MAILLAGE"));
  STELLA_ASSERT(meshData != nullptr, "MAILLAGE holds no mesh");
  auto model = std::make_shared<Model>(meshData->mesh);
  for (const KeywordTree& affe : kw.occurrences("AFFE")) {
    const auto cells = selectCells(*model->mesh, affe);
    assignModelling(*model, cells, affe.text("MODELISATION"), affe.locationOf("MODELISATION"));
  }
  finishModel(*model, call.location);
  int volumes = 0;
  int skins = 0;
  int discrete = 0;
  for (const auto& c : model->cells) {
    volumes += c.kind == ElementKind::Volume ? 1 : 0;
    skins += c.kind == ElementKind::Skin ? 1 : 0;
    discrete += c.kind == ElementKind::Discrete ? 1 : 0;
  }
  call.session.message() << fmt::format("   model {}: {} volume elements ({}), {} skin elements, {} discrete "
                                        "elements, {} components per node\n",
                                        call.resultName, volumes,
                                        model->hasVolume ? fem::modellingName(model->modelling) : "-", skins,
                                        discrete, model->components);
  return call.makeConcept(model);
}

} // namespace

STELLA_OPERATOR("AFFE_MODELE", runAffeModele);

} // namespace stella
