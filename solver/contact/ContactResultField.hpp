#pragma once
// CONT_NOEU: the nodal contact field on the slave nodes (quantity INFC_R, 30 components in
// code_aster's order), built from the pairing and the contact state of each link, with the
// reference's sign conventions:
//   CONT  -1 not paired, 0 no contact, 1 sticking (friction only), 2 sliding or any active
//         contact without friction;
//   JEU   gap, positive when open, negative when interpenetrated;
//   RN    norm of the nodal normal contact force; RNX/RNY/RNZ = lambda n (n the master outward
//         normal: the force the master exerts on the slave node);
//   GLIX/GLIY slip along the tangents, GLI its norm;
//   RTAX.. friction force of sticking nodes, RTGX.. of sliding nodes (global axes);
//   RX/RY/RZ/R total reaction RN + RTA + RTG and its norm; HN, I*, PT_* written 0 (discrete);
//   PROJ_X/Y/Z the projection of the slave node on the master surface.
// With RESOLUTION='NON' the forces are zero and only gaps are measured (CONT stays 0).
// Nodes that are not slave nodes carry no component (the field is partial).

#include "solver/contact/ContactPairing.hpp"
#include "solver/contact/PenaltyContact.hpp"
#include "solver/database/Field.hpp"

#include <array>
#include <memory>
#include <vector>

namespace stella {
struct ResultStep;
} // namespace stella

namespace stella::contact {

// The state of one link at the end of a step.
struct LinkState {
  double gap = 0.0;
  double normalForce = 0.0;             // lambda >= 0
  std::array<double, 2> slip{0, 0};     // along tangent1, tangent2
  std::array<double, 2> friction{0, 0}; // friction force along tangent1, tangent2
  LinkStatus status = LinkStatus::Open;
};

const std::vector<std::string>& contNoeuComponents();

// `states` parallel to `links`; `withFriction` decides whether an active link is sticking (1) or
// sliding (2).
Field buildContNoeu(std::size_t nodeCount, const std::vector<ContactLink>& links,
                    const std::vector<LinkState>& states, bool withFriction);

// Gap-only states (RESOLUTION='NON'): the pairing's gaps, no forces.
std::vector<LinkState> measuredGaps(const std::vector<ContactLink>& links);

// DEPL with the multiplier components `extra` appended (LAGS_C, LAGS_F1...), undefined until the
// caller fills them: the displacement values and their support copied, the field partial.
std::shared_ptr<Field> withMultiplierComponents(const Field& depl, const std::vector<std::string>& extra);

// The DEPL of `step` with LAGS_C appended, and with friction LAGS_F1 (and LAGS_F2 for two friction
// directions) after it (withMultiplierComponents): LAGS_C at component `first`, to be filled and
// stored back as DEPL. No field when the step has no DEPL or its DEPL already has LAGS_C.
struct MultiplierDepl {
  std::shared_ptr<Field> field;
  std::size_t first = 0;
};
MultiplierDepl multiplierDepl(const ResultStep& step, std::size_t frictionDirections);

} // namespace stella::contact
