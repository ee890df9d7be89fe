#include "solver/operators/EffectsReport.hpp"

#include "solver/inputs/Selection.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

std::string integrationOf(const std::string& relation) {
  return relation == "ELAS" ? "linear elasticity, no return mapping"
                            : "return mapping at each Gauss point (implicit, ITER_INTE_MAXI, RESI_INTE)";
}

// One line per COMPORTEMENT occurrence, and one for the cells it leaves (ELAS by default).
std::vector<std::string> behaviourLines(const KeywordTree& kw, const MechanicalSystem& system) {
  std::vector<std::string> lines;
  const Model& model = system.model();
  std::vector<bool> covered(model.cells.size(), false);
  int index = 0;
  for (const KeywordTree& occ : kw.occurrences("COMPORTEMENT")) {
    ++index;
    const std::string relation = occ.text("RELATION");
    const auto cells = selectCells(*model.mesh, occ);
    for (CellId c : cells) {
      covered[static_cast<std::size_t>(c)] = true;
    }
    const std::string where = occ.has("GROUP_MA")
                                  ? fmt::format("GROUP_MA=({})", fmt::join(occ.texts("GROUP_MA"), ", "))
                                  : std::string("TOUT='OUI'");
    const std::string deformation = occ.text("DEFORMATION");
    lines.push_back(fmt::format("behaviour {} on {} ({} cell(s)): {}, strains {}{} [COMPORTEMENT {}]",
                                relation, where, cells.size(), integrationOf(relation), deformation,
                                deformation == "GROT_GDEP"
                                    ? " (total Lagrangian: Green-Lagrange strain, PK2 stress in SIEF_ELGA, "
                                      "geometric stiffness in the tangent)"
                                    : "",
                                index));
  }
  std::size_t rest = 0;
  for (std::size_t c = 0; c < covered.size(); ++c) {
    rest += covered[c] || !system.behaviours().of(static_cast<CellId>(c)) ? 0 : 1;
  }
  if (rest > 0) {
    lines.push_back(
        fmt::format("behaviour ELAS on the {} other volume cell(s): {}, small strains [no COMPORTEMENT "
                    "for them: ELAS by default]",
                    rest, integrationOf("ELAS")));
  }
  return lines;
}

std::string factorisationLine(const MechanicalSystem& system, const NewtonSettings& settings,
                              const StepConstraint* constraint) {
  if (settings.symmetrizeTangent) {
    return "factorisation symmetric: (K + K^T) / 2 [NEWTON MATR_RIGI_SYME='OUI']";
  }
  if (!system.behaviours().allSymmetric()) {
    return "factorisation unsymmetric [a behaviour with an unsymmetric tangent]";
  }
  if (constraint != nullptr && constraint->zoneEffects().size() > 0 && !constraint->symmetric()) {
    return "factorisation unsymmetric [the contact tangent]";
  }
  return fmt::format("factorisation symmetric [every tangent symmetric{}]",
                     constraint != nullptr ? "; unsymmetric only while a penalised Coulomb slip makes the "
                                             "contact tangent so (COEF_MATR_FROT > 0, or the last "
                                             "iterations of a step)"
                                           : "");
}

} // namespace

std::string effectsReport(const KeywordTree& kw, const MechanicalSystem& system,
                          const NewtonSettings& settings, const StepConstraint* constraint,
                          const CutPolicy& cuts, bool observed) {
  std::vector<std::string> lines = behaviourLines(kw, system);
  lines.push_back(
      fmt::format("{} load(s), {} Lagrange multiplier(s) [EXCIT, the dualised DDL_IMPO and relations]",
                  system.excitations().size(), system.relationCount()));
  if (constraint == nullptr) {
    lines.push_back("no contact: no pairing, no contact structure, no friction [CONTACT absent]");
  } else {
    lines.push_back(constraint->effects() + " [CONTACT]");
    for (const std::string& zone : constraint->zoneEffects()) {
      lines.push_back("  " + zone + " [DEFI_CONTACT ZONE]");
    }
  }
  lines.push_back(factorisationLine(system, settings, constraint));
  lines.push_back(fmt::format(
      "Newton with the {} matrix{}, step cutting {}", settings.tangentMatrix ? "tangent" : "elastic",
      settings.lineSearch.enabled ? ", line search CORDE [RECH_LINEAIRE]" : "",
      cuts.subdivide ? fmt::format("SUBD_PAS={} SUBD_NIVEAU={}", cuts.subdivisions, cuts.maxLevel)
                     : std::string("off (ARRET)")));
  lines.push_back(
      fmt::format("fields stored at each archived step: DEPL, SIEF_ELGA, VARI_ELGA{}{} [ARCHIVAGE]",
                  constraint != nullptr ? ", CONT_NOEU" : "",
                  observed ? "; OBSERVATION evaluates its fields at its instants" : ""));
  std::string out = "   effects activated [why]:\n";
  for (const std::string& line : lines) {
    out += "     " + line + "\n";
  }
  return out;
}

std::string effectCosts(const PhaseTimes& phases, const MechanicalSystem& system, const NewtonDriver& driver,
                        const StepConstraint* constraint) {
  const std::string behaviours =
      system.behaviours().allLinear()
          ? std::string("elastic")
          : fmt::format("{}", fmt::join(system.behaviours().relationNames(), ", "));
  std::string contact;
  if (constraint != nullptr) {
    const std::string work = constraint->workSummary();
    contact = fmt::format(", contact {:.3f}{}", phases.contact, work.empty() ? "" : " (" + work + ")");
  }
  return fmt::format(
      "   time per effect (s): behaviours ({}) with assembly {:.3f}{}, factorisation {:.3f} ({} "
      "symmetric, {} unsymmetric), solve {:.3f}, fields stored {:.3f}, numbering {:.3f}, other "
      "{:.3f}\n",
      behaviours, phases.assembly, contact, phases.factorisation, driver.symmetricFactorisations(),
      driver.unsymmetricFactorisations(), phases.solve, phases.post, phases.numbering, phases.other);
}

} // namespace stella
