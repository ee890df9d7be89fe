#pragma once
// ADAPTATION='ADAPT_COEF' and 'TOUT' of the continuous formulation (notice §3.3.3, §4.12): the
// coefficients of the zone (COEF_CONT, COEF_PENA_CONT, COEF_FROT, COEF_PENA_FROT) are taken relative
// to the stiffness of the bodies in contact, so that a study gives the same dimensionless results
// in any units (issue 16). The scale of a zone is S = E* / h: E* the contact modulus of its two
// bodies, 1/E* = 1/E'_slave + 1/E'_master, E' = E / (1 - NU^2) averaged over the volume cells that
// hold a node of the surface, h the shortest edge of the zone's slave cells; each coefficient is its
// keyword's value (default 100) times S (a penalty COEF_PENA_CONT x S makes the contact spring of a
// node COEF_PENA_CONT times as stiff as a cell of the mesh). PENE_MAXI, when absent, is 1e-2 x the
// shortest edge of the zone's contact cells (notice §4.12); with ALGO_CONT='PENALISATION' the
// penalty is raised while the interpenetration exceeds it (ContinuousContactConstraint).

#include "solver/contact/ContactDefinition.hpp"
#include "solver/functions/InstantList.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <memory>

namespace stella {
class MaterialField;
namespace contact {

// The definition with the coefficients of its ADAPT_COEF/TOUT zones scaled and their PENE_MAXI set;
// `definition` itself when no zone adapts. `dimension`: 2 or 3 (the model's).
std::shared_ptr<const ContactDefinition>
adaptContinuousCoefficients(std::shared_ptr<const ContactDefinition> definition,
                            const MaterialField& materials, int dimension);

// Whether the zone's ADAPTATION scales its coefficients (ADAPT_COEF or TOUT).
bool adaptsCoefficients(const ContinuousZone& zone);

// The interpenetration control of the penalised zones (ContinuousPenetration.cpp), shared by the
// nodal and the point formulations: `penetration` the largest interpenetration of each zone at a
// converged state; the penalty factor of a zone above PENE_MAXI (ADAPT_COEF/TOUT) or above the
// DEFI_LIST_INST INTERPENETRATION event's is multiplied by 10 (at most COEF_MAXI). Returns the
// descriptions of the raises (empty: the state is accepted); throws CONTACT_14 (ACTION='ARRET');
// `alarm` receives CONTACT_15 and CONTACT_16.
std::vector<std::string> raisePenalties(const ContactDefinition& definition,
                                        const std::optional<FailurePolicy>& policy,
                                        const std::vector<double>& penetration, double time,
                                        std::vector<double>& factor,
                                        const std::function<void(std::string)>& alarm);
// The coefficients' adaptation and the interpenetration control, for the resolution's summary.
std::string penetrationEffects(const ContactDefinition& definition,
                               const std::optional<FailurePolicy>& policy);

} // namespace contact
} // namespace stella
