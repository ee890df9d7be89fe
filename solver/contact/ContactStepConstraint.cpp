// Building the contact constraint of STAT_NON_LINE from its CONTACT keyword (read by
// solver/inputs/ContactStepReader): the checks against the analysis (model, DOFs, what is not
// implemented yet) and the choice of the resolution.

#include "solver/contact/ContactStepConstraint.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/contact/ContinuousAdaptation.hpp"
#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/ContinuousPointContact.hpp"
#include "solver/contact/DualContactConstraint.hpp"
#include "solver/contact/PenaltyContactConstraint.hpp"
#include "solver/contact/lac/LacContactConstraint.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace stella {

namespace {

using contact::ContactAlgorithm;
using contact::ContactDefinition;

// The contact zones that are only measured (RESOLUTION='NON' everywhere) need no resolution.
class GapMeasurement : public contact::ContactConstraint {
public:
  using ContactConstraint::ContactConstraint;
  void addForces(const Eigen::VectorXd&, Eigen::VectorXd&, std::vector<Eigen::Triplet<double>>*) override {}
  bool symmetric() const override { return true; }
  void correct(const Eigen::VectorXd&, Eigen::VectorXd&, Eigen::VectorXd&, SaddleSolver&) override {}

protected:
  std::string resolutionEffects() const override {
    return "gap measurement only (RESOLUTION='NON': no contact force)";
  }
  std::vector<contact::LinkState> resolvedStates(const Eigen::VectorXd&) const override { return {}; }
};

[[noreturn]] void notImplemented(const std::string& what, const SourceLocation& at, const std::string& note) {
  throw UserError(msg::make("CONTACT_20", {{"what", what}}, at).withNote(note));
}

void checkAgainstSystem(const ContactDefinition& def, const MechanicalSystem& system,
                        const SourceLocation& at) {
  if (def.mesh.get() != system.model().mesh.get()) {
    throw UserError(msg::make("CONTACT_21", {}, at));
  }
  const Mesh& mesh = *def.mesh;
  for (const auto& zone : def.zones) {
    for (const std::string& group : {zone.masterGroup, zone.slaveGroup}) {
      const auto* cells = mesh.cellGroup(group);
      if (cells == nullptr) {
        continue;
      }
      for (NodeId n : mesh.nodesOfCells(*cells)) {
        if (system.dofs().dof(n, 0) < 0) {
          throw UserError(
              msg::make("CONTACT_6", {{"node_name", mesh.nodeName(n)}, {"group", group}}, zone.location));
        }
      }
    }
  }
}

// The algorithm of the resolved zones (one for all, as the discrete formulation solves them
// together); nullopt when every zone is only measured.
std::optional<ContactAlgorithm> resolvedAlgorithm(const ContactDefinition& def) {
  std::optional<ContactAlgorithm> algorithm;
  for (const auto& z : def.zones) {
    if (!z.resolve) {
      continue;
    }
    if (algorithm && *algorithm != z.algorithm) {
      notImplemented(fmt::format("zones with different ALGO_CONT ({} and {})",
                                 contact::algorithmName(*algorithm), contact::algorithmName(z.algorithm)),
                     z.location, "give every zone of the discrete formulation the same ALGO_CONT");
    }
    algorithm = z.algorithm;
  }
  return algorithm;
}

void refuse(const std::vector<contact::Unimplemented>& refused) {
  if (!refused.empty()) {
    notImplemented(fmt::format("{} with FORMULATION='CONTINUE'", refused.front().what),
                   refused.front().location,
                   "remove the keyword or give its default value; see doc/contact.md, \"Continuous "
                   "formulation\", for what is implemented");
  }
}

// FROTTEMENT='COULOMB' with ALGO_CONT='LAC' (lac/LacFriction.cpp): 2D and 3D, ALGO_FROT='STANDARD',
// ALGO_RESO_FROT='NEWTON', no SEUIL_INIT nor SANS_GROUP_NO_FR.
void refuseLacFriction(const ContactDefinition& def) {
  const std::string note = "LAC friction (beyond code_aster) is implemented with ALGO_FROT='STANDARD' and "
                           "ALGO_RESO_FROT='NEWTON'; use ALGO_CONT='STANDARD' for the rest";
  if (def.settings.continuous.frictionFixedPoint) {
    notImplemented("ALGO_RESO_FROT='POINT_FIXE' with ALGO_CONT='LAC'", def.settings.frictionAt, note);
  }
  for (const auto& z : def.zones) {
    if (z.continuous.frictionPenalised) {
      notImplemented("ALGO_FROT='PENALISATION' with ALGO_CONT='LAC'", z.location, note);
    }
    if (z.continuous.initialThreshold) {
      notImplemented("SEUIL_INIT with ALGO_CONT='LAC'", z.location, note);
    }
    if (!z.continuous.frictionExcludedGroups.empty()) {
      notImplemented("SANS_GROUP_NO_FR with ALGO_CONT='LAC'", z.continuous.frictionExcludedAt, note);
    }
  }
}

// ALGO_CONT='LAC' (every zone): 2D and 3D models, friction in 2D (LacContactConstraint.hpp).
std::unique_ptr<StepConstraint> makeLac(std::shared_ptr<const ContactDefinition> def,
                                        const MechanicalSystem& system,
                                        const std::optional<FailurePolicy>& policy,
                                        const SourceLocation& at) {
  refuse(def->settings.continuous.refused);
  for (const auto& z : def->zones) {
    if (z.algorithm != ContactAlgorithm::Lac) {
      notImplemented(fmt::format("a zone with ALGO_CONT='{}' beside zones with ALGO_CONT='LAC'",
                                 contact::algorithmName(z.algorithm)),
                     z.location, "give every zone ALGO_CONT='LAC', or none");
    }
  }
  if (def->hasFriction()) {
    refuseLacFriction(*def);
  }
  const fem::Modelling modelling = system.model().modelling;
  if (def->settings.smoothing && modelling == fem::Modelling::ThreeD) {
    notImplemented("LISSAGE='OUI' with ALGO_CONT='LAC' in 3D", def->location,
                   "LAC in 3D uses the normals of the slave faces; remove LISSAGE (it is implemented in 2D)");
  }
  if (policy) {
    notImplemented("DEFI_LIST_INST EVENEMENT='INTERPENETRATION' with ALGO_CONT='LAC'", at,
                   "remove the INTERPENETRATION event");
  }
  return std::make_unique<contact::lac::LacContactConstraint>(std::move(def), system.dofs(), modelling);
}

// INTEGRATION with contact points off the slave nodes (GAUSS, SIMPSON, NCOTES; AUTO on TRIA6/QUAD8):
// the master's normal only (friction, SEUIL_INIT, GLISSIERE, SANS_GROUP_NO_FR as at the nodes).
void refuseAtPoints(const ContactDefinition& def) {
  const std::string note =
      "contact points off the slave nodes (ContinuousPointContact) are implemented with "
      "NORMALE='MAIT', VECT_MAIT=VECT_ESCL='AUTO' and LISSAGE='NON'; use INTEGRATION='AUTO' on "
      "TRIA3, QUAD4, QUAD9 (SEG2, SEG3) slave cells for the rest";
  if (def.settings.smoothing) {
    notImplemented("LISSAGE='OUI' with INTEGRATION other than 'AUTO' on linear cells", def.location, note);
  }
  for (const auto& z : def.zones) {
    const SourceLocation& at = z.continuous.integration != contact::ContactIntegration::Auto
                                   ? z.continuous.integrationAt
                                   : z.location;
    if (z.normal != contact::NormalChoice::Master || z.masterVector != contact::VectorChoice::Auto ||
        z.slaveVector != contact::VectorChoice::Auto) {
      notImplemented(
          "NORMALE other than 'MAIT' (or VECT_MAIT/VECT_ESCL) with INTEGRATION other than 'AUTO' on "
          "linear cells",
          at, note);
    }
  }
}

// ALGO_RESO_GEOM='NEWTON' has the geometric tangent of the master's own normal at the slave nodes,
// with Coulomb friction on the pairing's tangents (ContinuousGeometricTangent.hpp).
void refuseGeometryNewton(const ContactDefinition& def) {
  const SourceLocation& at = def.settings.continuous.geometryAt;
  const std::string note = "use ALGO_RESO_GEOM='POINT_FIXE' (the geometric loop, REAC_GEOM)";
  for (const auto& z : def.zones) {
    if (def.hasFriction() && z.continuous.excludedDirection && def.mesh->dimension() == 3) {
      notImplemented("ALGO_RESO_GEOM='NEWTON' and DIRE_EXCL_FROT in 3D with FORMULATION='CONTINUE'",
                     z.continuous.excludedDirectionAt,
                     "the friction direction DIRE_EXCL_FROT leaves turns with the geometry and its variation "
                     "is not in the tangent; " +
                         note);
    }
  }
  if (def.settings.smoothing) {
    notImplemented("ALGO_RESO_GEOM='NEWTON' and LISSAGE='OUI' with FORMULATION='CONTINUE'", at, note);
  }
  if (contact::needsContactPoints(def)) {
    notImplemented("ALGO_RESO_GEOM='NEWTON' and contact points that are not slave nodes (INTEGRATION "
                   "other than 'AUTO', or 'AUTO' on TRIA6 and QUAD8 slave cells) with FORMULATION='CONTINUE'",
                   at, note);
  }
  for (const auto& z : def.zones) {
    if (z.normal != contact::NormalChoice::Master || z.masterVector != contact::VectorChoice::Auto ||
        z.slaveVector != contact::VectorChoice::Auto || z.pairing != contact::Pairing::MasterSlave) {
      notImplemented("ALGO_RESO_GEOM='NEWTON' and NORMALE other than 'MAIT', VECT_MAIT, VECT_ESCL or "
                     "APPARIEMENT other than 'MAIT_ESCL' with FORMULATION='CONTINUE' (the geometric tangent "
                     "is that of the master's own normal)",
                     z.location, note);
    }
  }
}

// FORMULATION='CONTINUE': what is not implemented yet is refused, naming the keyword.
std::unique_ptr<contact::ContactConstraint> makeContinuous(std::shared_ptr<const ContactDefinition> def,
                                                           const MechanicalSystem& system,
                                                           const std::optional<FailurePolicy>& policy,
                                                           const SourceLocation& at) {
  refuse(def->settings.continuous.refused);
  if (def->settings.continuous.geometryNewton) {
    refuseGeometryNewton(*def);
  }
  for (const auto& z : def->zones) {
    refuse(z.continuous.refused);
    if (def->hasFriction() && z.algorithm == ContactAlgorithm::ContinuePenalty) {
      notImplemented("FROTTEMENT='COULOMB' with ALGO_CONT='PENALISATION' and FORMULATION='CONTINUE'",
                     z.location,
                     "use ALGO_CONT='STANDARD' (COEF_CONT) with ALGO_FROT='STANDARD' or 'PENALISATION'");
    }
  }
  if (policy && std::none_of(def->zones.begin(), def->zones.end(), [](const contact::ContactZone& z) {
        return z.resolve && z.algorithm == ContactAlgorithm::ContinuePenalty;
      })) {
    notImplemented(
        "DEFI_LIST_INST EVENEMENT='INTERPENETRATION' without a zone of ALGO_CONT='PENALISATION' (it "
        "raises COEF_PENA_CONT; the augmented Lagrangian leaves no interpenetration)",
        at, "use ALGO_CONT='PENALISATION', or remove the INTERPENETRATION event");
  }
  def = contact::adaptContinuousCoefficients(std::move(def), system.materials(),
                                             fem::spaceDimension(system.model().modelling));
  if (contact::needsContactPoints(*def)) {
    refuseAtPoints(*def);
    auto p = std::make_unique<contact::ContinuousPointContactConstraint>(std::move(def), system.dofs(),
                                                                         system.model().modelling);
    p->setInterpenetrationPolicy(policy);
    return p;
  }
  auto c = std::make_unique<contact::ContinuousContactConstraint>(std::move(def), system.dofs(),
                                                                  system.model().modelling);
  c->setInterpenetrationPolicy(policy);
  return c;
}

} // namespace

std::unique_ptr<StepConstraint> makeContactConstraint(const ContactStepInputs& inputs,
                                                      MechanicalSystem& system, int threads) {
  const SourceLocation& at = inputs.at;
  const std::shared_ptr<const ContactDefinition>& def = inputs.definition;
  if (def->settings.formulation == contact::Formulation::LiaisonUnil) {
    notImplemented("FORMULATION='LIAISON_UNIL'", def->location,
                   "FORMULATION='DISCRETE' or 'CONTINUE' are available");
  }
  checkAgainstSystem(*def, system, at);
  const std::optional<FailurePolicy>& policy = inputs.interpenetration;
  const bool lac = std::any_of(def->zones.begin(), def->zones.end(),
                               [](const auto& z) { return z.algorithm == ContactAlgorithm::Lac; });
  if (def->settings.formulation == contact::Formulation::Continue && lac) {
    return makeLac(def, system, policy, at);
  }
  if (def->settings.formulation == contact::Formulation::Continue) {
    auto c = makeContinuous(def, system, policy, at);
    c->initialize();
    return c;
  }
  const std::optional<ContactAlgorithm> algorithm = resolvedAlgorithm(*def);
  std::unique_ptr<contact::ContactConstraint> c;
  if (!algorithm) {
    c = std::make_unique<GapMeasurement>(def, system.dofs());
  } else if (*algorithm == ContactAlgorithm::Penalty) {
    c = std::make_unique<contact::PenaltyContactConstraint>(def, system.dofs(), policy);
  } else {
    if (def->hasFriction()) {
      notImplemented(
          fmt::format("FROTTEMENT='COULOMB' with ALGO_CONT='{}' (dual contact with penalised friction)",
                      contact::algorithmName(*algorithm)),
          def->location, "use ALGO_CONT='PENALISATION' with E_N for contact with friction");
    }
    if (*algorithm == ContactAlgorithm::Gcp && !def->settings.gcpTolerance) {
      throw UserError(msg::make("CONTACT_24", {}, def->location));
    }
    if (policy) {
      notImplemented(
          fmt::format("DEFI_LIST_INST EVENEMENT='INTERPENETRATION' (ACTION='{}') with ALGO_CONT='{}' "
                      "(it acts on ALGO_CONT='PENALISATION')",
                      policy->action == FailurePolicy::Action::AdaptPenalty ? "ADAPT_COEF_PENA" : "ARRET",
                      contact::algorithmName(*algorithm)),
          at, "use ALGO_CONT='PENALISATION', or remove the INTERPENETRATION event");
    }
    c = std::make_unique<contact::DualContactConstraint>(def, system.dofs(), *algorithm);
  }
  c->setPairingThreads(threads);
  c->initialize();
  return c;
}

} // namespace stella
