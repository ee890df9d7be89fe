// DEFI_MATERIAU: ELAS (E, NU, RHO, ALPHA) and ECRO_LINE (D_SIGM_EPSI, SY); other parameter sets
// are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/model/Material.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

void refuse(const KeywordTree& kw, const std::string& name) {
  if (kw.has(name)) {
    throw UserError(msg::make("MATER_1", {{"name", name}}, kw.locationOf(name)));
  }
}

// A material value that is not a finite number (float('nan'), float('inf'), 1e400) would only
// show later as a singular system blamed on the supports: refused here, at the keyword.
double finiteReal(const KeywordTree& kw, const std::string& factor, const std::string& name) {
  const double value = kw.real(name);
  if (!std::isfinite(value)) {
    throw UserError(
        msg::make("MATER_4.2", {{"factor", factor}, {"name", name}, {"value", value}}, kw.locationOf(name)));
  }
  return value;
}

void refuseOutside(const KeywordTree& kw, const std::string& name, double value, bool valid,
                   const std::string& expected) {
  if (!valid) {
    throw UserError(msg::make("MATER_2", {{"name", name}, {"value", value}, {"expected", expected}},
                              kw.locationOf(name)));
  }
}

ElasticMaterial readElastic(const KeywordTree& elas) {
  ElasticMaterial e;
  e.youngModulus = finiteReal(elas, "ELAS", "E");
  e.poissonRatio = finiteReal(elas, "ELAS", "NU");
  refuseOutside(elas, "E", e.youngModulus, e.youngModulus > 0.0, "E > 0");
  refuseOutside(elas, "NU", e.poissonRatio, e.poissonRatio > -1.0 && e.poissonRatio < 0.5,
                "-1 < NU < 0.5 (the elastic energy is positive only there)");
  if (elas.has("RHO")) {
    const double density = finiteReal(elas, "ELAS", "RHO");
    refuseOutside(elas, "RHO", density, density >= 0.0, "RHO >= 0");
    e.density = density;
  }
  if (elas.has("ALPHA")) {
    e.expansion = finiteReal(elas, "ELAS", "ALPHA");
  }
  return e;
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
      throw UserError(msg::make("MATER_1.2", {}, elas.location()));
    }
    material->elastic = readElastic(elas);
  }
  if (kw.has("ECRO_LINE")) {
    const KeywordTree& ecro = kw.occurrences("ECRO_LINE").front();
    LinearHardeningMaterial h{finiteReal(ecro, "ECRO_LINE", "D_SIGM_EPSI"),
                              finiteReal(ecro, "ECRO_LINE", "SY")};
    if (h.yieldStress <= 0.0 || h.tangentModulus < 0.0 ||
        (material->elastic && h.tangentModulus >= material->elastic->youngModulus)) {
      throw UserError(msg::make("MATER_3",
                                {{"yield_stress", h.yieldStress}, {"tangent_modulus", h.tangentModulus}},
                                ecro.location()));
    }
    material->hardening = h;
  }
  return call.makeConcept(material);
}

} // namespace

STELLA_OPERATOR("DEFI_MATERIAU", runDefiMateriau);

} // namespace stella
