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
      notImplemented(msg::text("CONTACT_20.mixed_algo", {{"first", contact::algorithmName(*algorithm)},
                                                         {"second", contact::algorithmName(z.algorithm)}}),
                     z.location, msg::text("CONTACT_20.mixed_algo_n"));
    }
    algorithm = z.algorithm;
  }
  return algorithm;
}

void refuse(const std::vector<contact::Unimplemented>& refused) {
  if (!refused.empty()) {
    notImplemented(msg::text("CONTACT_20.continue_kw", {{"what", refused.front().what}}),
                   refused.front().location, msg::text("CONTACT_20.continue_kw_n"));
  }
}

// FROTTEMENT='COULOMB' with ALGO_CONT='LAC' (lac/LacFriction.cpp): 2D and 3D, ALGO_FROT='STANDARD',
// ALGO_RESO_FROT='NEWTON', no SEUIL_INIT nor SANS_GROUP_NO_FR.
void refuseLacFriction(const ContactDefinition& def) {
  const std::string note = msg::text("CONTACT_20.lac_friction_n");
  if (def.settings.continuous.frictionFixedPoint) {
    notImplemented(msg::text("CONTACT_20.lac_frot_pf"), def.settings.frictionAt, note);
  }
  for (const auto& z : def.zones) {
    if (z.continuous.frictionPenalised) {
      notImplemented(msg::text("CONTACT_20.lac_frot_pena"), z.location, note);
    }
    if (z.continuous.initialThreshold) {
      notImplemented(msg::text("CONTACT_20.lac_seuil"), z.location, note);
    }
    if (!z.continuous.frictionExcludedGroups.empty()) {
      notImplemented(msg::text("CONTACT_20.lac_sans_fr"), z.continuous.frictionExcludedAt, note);
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
      notImplemented(msg::text("CONTACT_20.lac_mixed", {{"algo", contact::algorithmName(z.algorithm)}}),
                     z.location, msg::text("CONTACT_20.lac_mixed_n"));
    }
  }
  if (def->hasFriction()) {
    refuseLacFriction(*def);
  }
  const fem::Modelling modelling = system.model().modelling;
  if (def->settings.smoothing && modelling == fem::Modelling::ThreeD) {
    notImplemented(msg::text("CONTACT_20.lac_lissage_3d"), def->location,
                   msg::text("CONTACT_20.lac_lissage_3d_n"));
  }
  if (policy) {
    notImplemented(msg::text("CONTACT_20.lac_interpen"), at, msg::text("CONTACT_20.lac_interpen_n"));
  }
  return std::make_unique<contact::lac::LacContactConstraint>(std::move(def), system.dofs(), modelling);
}

// INTEGRATION with contact points off the slave nodes (GAUSS, SIMPSON, NCOTES; AUTO on TRIA6/QUAD8):
// the master's normal only (friction, SEUIL_INIT, GLISSIERE, SANS_GROUP_NO_FR as at the nodes).
void refuseAtPoints(const ContactDefinition& def) {
  const std::string note = msg::text("CONTACT_20.points_n");
  if (def.settings.smoothing) {
    notImplemented(msg::text("CONTACT_20.points_lissage"), def.location, note);
  }
  for (const auto& z : def.zones) {
    const SourceLocation& at = z.continuous.integration != contact::ContactIntegration::Auto
                                   ? z.continuous.integrationAt
                                   : z.location;
    if (z.normal != contact::NormalChoice::Master || z.masterVector != contact::VectorChoice::Auto ||
        z.slaveVector != contact::VectorChoice::Auto) {
      notImplemented(msg::text("CONTACT_20.points_normale"), at, note);
    }
  }
}

// ALGO_RESO_GEOM='NEWTON' has the geometric tangent of the master's own normal at the slave nodes,
// with Coulomb friction on the pairing's tangents (ContinuousGeometricTangent.hpp).
void refuseGeometryNewton(const ContactDefinition& def) {
  const SourceLocation& at = def.settings.continuous.geometryAt;
  const std::string note = msg::text("CONTACT_20.geom_n");
  for (const auto& z : def.zones) {
    if (def.hasFriction() && z.continuous.excludedDirection && def.mesh->dimension() == 3) {
      notImplemented(msg::text("CONTACT_20.geom_dire_excl"), z.continuous.excludedDirectionAt,
                     msg::text("CONTACT_20.geom_dire_excl_n", {{"advice", note}}));
    }
  }
  if (def.settings.smoothing) {
    notImplemented(msg::text("CONTACT_20.geom_lissage"), at, note);
  }
  if (contact::needsContactPoints(def)) {
    notImplemented(msg::text("CONTACT_20.geom_points"), at, note);
  }
  for (const auto& z : def.zones) {
    if (z.normal != contact::NormalChoice::Master || z.masterVector != contact::VectorChoice::Auto ||
        z.slaveVector != contact::VectorChoice::Auto || z.pairing != contact::Pairing::MasterSlave) {
      notImplemented(msg::text("CONTACT_20.geom_normale"), z.location, note);
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
      notImplemented(msg::text("CONTACT_20.cont_pena_frot"), z.location,
                     msg::text("CONTACT_20.cont_pena_frot_n"));
    }
  }
  if (policy && std::none_of(def->zones.begin(), def->zones.end(), [](const contact::ContactZone& z) {
        return z.resolve && z.algorithm == ContactAlgorithm::ContinuePenalty;
      })) {
    notImplemented(msg::text("CONTACT_20.cont_interpen"), at, msg::text("CONTACT_20.interpen_n"));
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
    notImplemented(msg::text("CONTACT_20.liaison_unil"), def->location,
                   msg::text("CONTACT_20.liaison_unil_n"));
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
      notImplemented(msg::text("CONTACT_20.dual_frot", {{"algo", contact::algorithmName(*algorithm)}}),
                     def->location, msg::text("CONTACT_20.dual_frot_n"));
    }
    if (*algorithm == ContactAlgorithm::Gcp && !def->settings.gcpTolerance) {
      throw UserError(msg::make("CONTACT_24", {}, def->location));
    }
    if (policy) {
      notImplemented(
          msg::text("CONTACT_20.dual_interpen",
                    {{"action",
                      policy->action == FailurePolicy::Action::AdaptPenalty ? "ADAPT_COEF_PENA" : "ARRET"},
                     {"algo", contact::algorithmName(*algorithm)}}),
          at, msg::text("CONTACT_20.interpen_n"));
    }
    c = std::make_unique<contact::DualContactConstraint>(def, system.dofs(), *algorithm);
  }
  c->setPairingThreads(threads);
  c->initialize();
  return c;
}

} // namespace stella
