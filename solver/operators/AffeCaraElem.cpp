// AFFE_CARA_ELEM: element characteristics (discrete spring stiffnesses DISCRET / DISCRET_2D
// K_T_D_N) on a model (solver/model/ElementCharacteristics).

#include "interpreter/Diagnostics.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/ElementCharacteristicsReader.hpp"
#include "solver/model/Model.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

Value runAffeCaraElem(OperatorCall& call) {
  auto model = conceptData<Model>(call.keywords.conceptValue("MODELE"));
  STELLA_ASSERT(model != nullptr, "MODELE holds no model");
  auto cara = std::make_shared<ElementCharacteristics>();
  cara->model = model;
  readElementCharacteristics(call.keywords, *cara);
  call.session.message() << fmt::format(
      "   characteristics {}: {} discrete spring(s) (K_T_D_N) of {} discrete "
      "element(s) of the model\n",
      call.resultName, cara->springs.size(), model->cellsOfKind(ElementKind::Discrete).size());
  return call.makeConcept(cara);
}

} // namespace

STELLA_OPERATOR("AFFE_CARA_ELEM", runAffeCaraElem);

} // namespace stella
