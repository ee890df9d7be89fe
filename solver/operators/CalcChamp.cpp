// CALC_CHAMP: fields computed from a result's stored fields. Implemented: FORCE FORC_NODA (the
// nodal forces B^T sigma of SIEF_ELGA) and REAC_NODA (FORC_NODA minus the external forces of
// the loads the result was computed with, so non-zero only where supports react). The other
// options are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "solver/database/Result.hpp"
#include "solver/model/MaterialField.hpp"
#include "solver/nonlinear/ExternalForces.hpp"
#include "solver/nonlinear/NodalForces.hpp"
#include "solver/nonlinear/ResultFields.hpp"
#include "solver/nonlinear/ResultLoads.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

std::vector<ResultStep*> selectedSteps(Result& result, const KeywordTree& kw) {
  std::vector<ResultStep*> out;
  for (ResultStep& s : result.steps) {
    bool take = true;
    if (kw.has("NUME_ORDRE")) {
      const auto n = kw.integers("NUME_ORDRE");
      take = std::find(n.begin(), n.end(), s.number) != n.end();
    } else if (kw.has("INST")) {
      take = false;
      for (double t : kw.reals("INST")) {
        take = take || std::fabs(t - s.time) <= 1.0e-6 * std::max(1.0, std::fabs(t));
      }
    }
    if (take) {
      out.push_back(&s);
    }
  }
  if (out.empty()) {
    throw UserError(Diagnostic::fatal("CALC_1", "no stored step matches NUME_ORDRE / INST", kw.location()));
  }
  return out;
}

void refuseOthers(const KeywordTree& kw) {
  for (const char* k :
       {"CONTRAINTE", "DEFORMATION", "ENERGIE", "CRITERES", "VARI_INTERNE", "HYDRAULIQUE", "ERREUR",
        "METALLURGIE", "PROPRIETES", "CHAM_UTIL", "LIST_INST", "LIST_ORDRE", "EXCIT"}) {
    if (kw.has(k)) {
      throw UserError(Diagnostic::fatal("CALC_2", fmt::format("CALC_CHAMP {} is not implemented yet", k),
                                        kw.locationOf(k))
                          .withNote("implemented: FORCE=('FORC_NODA', 'REAC_NODA')"));
    }
  }
}

Value runCalcChamp(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  refuseOthers(kw);
  auto concept_ = kw.conceptValue("RESULTAT");
  auto source = conceptData<Result>(concept_);
  STELLA_ASSERT(source != nullptr, "RESULTAT holds no result");
  auto model = std::dynamic_pointer_cast<Model>(source->model);
  if (!model) {
    throw UserError(Diagnostic::fatal("CALC_3", fmt::format("result {} carries no model", concept_->name),
                                      kw.locationOf("RESULTAT")));
  }
  auto materials = std::dynamic_pointer_cast<MaterialField>(source->material);
  // Without reuse=, the new result shares the fields of the source and gets the new ones.
  std::shared_ptr<Result> result = call.reused ? source : std::make_shared<Result>(*source);
  const DofMap dofs(*model);
  const auto* loads = rememberedLoads(*source);
  std::vector<Eigen::VectorXd> cache;
  const auto options = kw.has("FORCE") ? kw.texts("FORCE") : std::vector<std::string>{};
  for (ResultStep* step : selectedSteps(*result, kw)) {
    const Field* sief = step->field("SIEF_ELGA");
    if (sief == nullptr) {
      throw UserError(
          Diagnostic::fatal("CALC_4",
                            fmt::format("result {} has no SIEF_ELGA at NUME_ORDRE {}: FORC_NODA and "
                                        "REAC_NODA need it",
                                        concept_->name, step->number),
                            kw.locationOf("FORCE")));
    }
    const Eigen::VectorXd forc = forcesFromStress(*model, dofs, *sief);
    for (const auto& option : options) {
      if (option == "FORC_NODA") {
        step->fields["FORC_NODA"] = nodalField(*model, dofs, forc, "DEPL_R");
        continue;
      }
      if (loads == nullptr) {
        throw UserError(Diagnostic::fatal(
            "CALC_5",
            fmt::format("the loads of result {} are unknown, REAC_NODA cannot be formed", concept_->name),
            kw.locationOf("FORCE")));
      }
      const Eigen::VectorXd fext = externalForces(*loads, step->time, dofs, materials.get(), cache);
      step->fields["REAC_NODA"] = nodalField(*model, dofs, forc - fext, "DEPL_R");
    }
  }
  if (loads != nullptr && !call.reused) {
    rememberLoads(result, *loads);
  }
  return call.makeConcept(result);
}

} // namespace

STELLA_OPERATOR("CALC_CHAMP", runCalcChamp);

} // namespace stella
