// AFFE_CHAR_CINE: displacements imposed by elimination (MECA_IMPO).

#include "interpreter/Diagnostics.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/LoadReader.hpp"
#include "solver/session/OperatorRegistry.hpp"

namespace stella {

namespace {

Value runAffeCharCine(OperatorCall& call) {
  auto model = conceptData<Model>(call.keywords.conceptValue("MODELE"));
  STELLA_ASSERT(model != nullptr, "MODELE holds no model");
  auto load = std::make_shared<KinematicLoad>();
  load->model = model;
  readKinematicLoad(call.keywords, *load);
  return call.makeConcept(load);
}

} // namespace

STELLA_OPERATOR("AFFE_CHAR_CINE", runAffeCharCine);

} // namespace stella
