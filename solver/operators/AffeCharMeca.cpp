// AFFE_CHAR_MECA: dualised kinematic conditions and loads on a model (solver/inputs/LoadReader).

#include "interpreter/Diagnostics.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/LoadReader.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

Value runAffeCharMeca(OperatorCall& call) {
  auto model = conceptData<Model>(call.keywords.conceptValue("MODELE"));
  STELLA_ASSERT(model != nullptr, "MODELE holds no model");
  auto load = std::make_shared<MechanicalLoad>();
  load->model = model;
  readMechanicalLoad(call.keywords, *load);
  call.session.message() << fmt::format(
      "   load {}: {} linear relations (Lagrange multipliers), {} nodal forces, "
      "{} pressured skin cells, {} skin cells with forces, {} volume cells "
      "with forces, {} gravity loads\n",
      call.resultName, load->relations.size(), load->nodalForces.size(), load->pressures.size(),
      load->surfaceForces.size(), load->volumeForces.size(), load->gravity.size());
  return call.makeConcept(load);
}

} // namespace

STELLA_OPERATOR("AFFE_CHAR_MECA", runAffeCharMeca);

} // namespace stella
