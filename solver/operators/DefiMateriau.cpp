// DEFI_MATERIAU: ELAS (E, NU, RHO, ALPHA) and ECRO_LINE (D_SIGM_EPSI, SY); other parameter sets
// are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "solver/model/Material.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

void refuse(const KeywordTree& kw, const std::string& name) {
  if (kw.has(name)) {
    throw UserError(Diagnostic::fatal("MATER_1", fmt::format("DEFI_MATERIAU {} is not implemented yet", name),
                                      kw.locationOf(name))
                        .withNote("available: ELAS (E, NU, RHO, ALPHA) and ECRO_LINE (D_SIGM_EPSI, SY)"));
  }
}

Value runDefiMateriau(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  for (const char* name : {"ELAS_FO", "ECRO_PUIS", "TRACTION", "PRAGER", "MATER"}) {
    refuse(kw, name);
  }
  auto material = std::make_shared<Material>();
  material->name = call.resultName;
  if (kw.has("ELAS")) {
    const KeywordTree& elas = kw.occurrences("ELAS").front();
    if (!elas.has("E")) {
      throw UserError(Diagnostic::fatal("MATER_1",
                                        "ELAS with K and MU or CELE_P and CELE_S is not implemented yet",
                                        elas.location())
                          .withNote("give E and NU"));
    }
    ElasticMaterial e;
    e.youngModulus = elas.real("E");
    e.poissonRatio = elas.real("NU");
    if (e.youngModulus <= 0.0 || e.poissonRatio >= 0.5) {
      throw UserError(Diagnostic::fatal(
          "MATER_2",
          fmt::format("ELAS needs E > 0 and NU < 0.5 (got E = {}, NU = {})", e.youngModulus, e.poissonRatio),
          elas.location()));
    }
    if (elas.has("RHO")) {
      e.density = elas.real("RHO");
    }
    if (elas.has("ALPHA")) {
      e.expansion = elas.real("ALPHA");
    }
    material->elastic = e;
  }
  if (kw.has("ECRO_LINE")) {
    const KeywordTree& ecro = kw.occurrences("ECRO_LINE").front();
    LinearHardeningMaterial h{ecro.real("D_SIGM_EPSI"), ecro.real("SY")};
    if (h.yieldStress <= 0.0 || h.tangentModulus < 0.0 ||
        (material->elastic && h.tangentModulus >= material->elastic->youngModulus)) {
      throw UserError(
          Diagnostic::fatal("MATER_3",
                            fmt::format("ECRO_LINE needs SY > 0 and 0 <= D_SIGM_EPSI < E (got SY = {}, "
                                        "D_SIGM_EPSI = {})",
                                        h.yieldStress, h.tangentModulus),
                            ecro.location()));
    }
    material->hardening = h;
  }
  return call.makeConcept(material);
}

} // namespace

STELLA_OPERATOR("DEFI_MATERIAU", runDefiMateriau);

} // namespace stella
