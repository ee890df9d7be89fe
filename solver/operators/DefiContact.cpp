// DEFI_CONTACT: reads the contact zones and settings into a char_contact concept
// (solver/contact/ContactDefinition) and checks them against the model's mesh.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/contact/ContactDefinition.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/inputs/ContactReader.hpp"
#include "solver/model/Model.hpp"
#include "solver/operators/CoincidentNodesAlarm.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

// Every node of a contact surface must carry displacement DOFs (notice §2.1).
void checkNodesCarryDofs(const contact::ContactDefinition& def, const Model& model) {
  const Mesh& mesh = *def.mesh;
  for (const auto& zone : def.zones) {
    for (const std::string& group : {zone.masterGroup, zone.slaveGroup}) {
      const auto* cells = mesh.cellGroup(group);
      if (cells == nullptr) {
        continue;
      }
      for (NodeId n : mesh.nodesOfCells(*cells)) {
        if (!model.nodeActive(n)) {
          throw UserError(
              msg::make("CONTACT_6.2", {{"node_name", mesh.nodeName(n)}, {"group", group}}, zone.location));
        }
      }
    }
  }
}

Value runDefiContact(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  auto model = conceptData<Model>(kw.conceptValue("MODELE"));
  STELLA_ASSERT(model != nullptr, "MODELE holds no model");
  auto def = contact::readContactDefinition(kw, model->mesh);
  def->model = model;
  contact::checkContactDefinition(*def);
  if (def->settings.formulation != contact::Formulation::LiaisonUnil) {
    checkNodesCarryDofs(*def, *model);
  }
  dropPairsJoinedByContact(call.session, *def);
  static const char* formulations[] = {"DISCRETE", "CONTINUE", "LIAISON_UNIL"};
  call.session.message() << fmt::format("   contact {}: formulation {}, {} zone(s){}\n", call.resultName,
                                        formulations[static_cast<int>(def->settings.formulation)],
                                        def->zones.size(), def->hasFriction() ? ", Coulomb friction" : "");
  for (std::size_t i = 0; i < def->zones.size(); ++i) {
    const auto& z = def->zones[i];
    call.session.message() << fmt::format(
        "     zone {}: master '{}', slave '{}' ({} slave nodes), ALGO_CONT {}{}\n", i + 1, z.masterGroup,
        z.slaveGroup, contact::zoneSlaveNodes(*def->mesh, z).size(), contact::algorithmName(z.algorithm),
        z.resolve ? "" : ", RESOLUTION='NON' (gaps measured only)");
  }
  return call.makeConcept(def);
}

} // namespace

STELLA_OPERATOR("DEFI_CONTACT", runDefiContact);

} // namespace stella
