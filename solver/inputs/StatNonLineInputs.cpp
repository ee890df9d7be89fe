// StatNonLineInputs: keyword trees of STAT_NON_LINE -> settings of the driver and stepper.

#include "solver/inputs/StatNonLineInputs.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/nonlinear/ResultFields.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

[[noreturn]] void notImplemented(const KeywordTree& kw, const std::string& name, const std::string& what) {
  throw UserError(msg::make("SNL_1", {{"what", what}}, kw.locationOf(name)));
}

Prediction readPrediction(const KeywordTree& nw, bool tangentMatrix) {
  const std::string p = nw.textOr("PREDICTION", tangentMatrix ? "TANGENTE" : "ELASTIQUE");
  if (p == "TANGENTE") {
    return Prediction::Tangent;
  }
  if (p == "ELASTIQUE") {
    return Prediction::Elastic;
  }
  if (p == "EXTRAPOLE") {
    return Prediction::Extrapolated;
  }
  return Prediction::Computed;
}

// NEWTON/EVOL_NOLI for PREDICTION='DEPL_CALCULE': its displacement at a time, linear between
// stored steps.
std::function<Eigen::VectorXd(double)> computedDisplacement(const KeywordTree& nw,
                                                            const MechanicalSystem& system) {
  if (!nw.has("EVOL_NOLI")) {
    throw UserError(msg::make("SNL_7", {}, nw.locationOf("PREDICTION")));
  }
  auto result = conceptData<Result>(nw.conceptValue("EVOL_NOLI"));
  if (!result || result->mesh.get() != system.model().mesh.get() || result->steps.empty()) {
    throw UserError(msg::make("SNL_7.2", {}, nw.locationOf("EVOL_NOLI")));
  }
  const SourceLocation at = nw.locationOf("EVOL_NOLI");
  const DofMap& dofs = system.dofs();
  return [result, &dofs, at](double time) -> Eigen::VectorXd {
    const auto& steps = result->steps;
    const double tolerance = 1.0e-9 * std::max(1.0, std::fabs(time));
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const Field* d = steps[i].field("DEPL");
      if (d != nullptr && std::fabs(steps[i].time - time) <= tolerance) {
        return displacementVector(*d, dofs);
      }
      if (i + 1 < steps.size() && steps[i].time < time && time < steps[i + 1].time) {
        const Field* e = steps[i + 1].field("DEPL");
        if (d != nullptr && e != nullptr) {
          const double w = (time - steps[i].time) / (steps[i + 1].time - steps[i].time);
          return (1.0 - w) * displacementVector(*d, dofs) + w * displacementVector(*e, dofs);
        }
      }
    }
    throw UserError(msg::make("SNL_7.3", {{"time", time}}, at));
  };
}

void readLineSearch(const KeywordTree& kw, NewtonSettings& s) {
  if (!kw.has("RECH_LINEAIRE") || kw.factor("RECH_LINEAIRE")->defaulted) {
    return;
  }
  const KeywordTree& ls = kw.occurrences("RECH_LINEAIRE").front();
  // METHODE: the catalogue implements 'CORDE' only (implemente=).
  if (kw.has("CONTACT")) {
    notImplemented(kw, "RECH_LINEAIRE", msg::text("SNL_1.f1"));
  }
  s.lineSearch.enabled = true;
  s.lineSearch.maxIterations = static_cast<int>(ls.integer("ITER_LINE_MAXI"));
  s.lineSearch.relativeResidual = ls.real("RESI_LINE_RELA");
  s.lineSearch.rhoMin = ls.real("RHO_MIN");
  s.lineSearch.rhoMax = ls.real("RHO_MAX");
  s.lineSearch.rhoExcluded = ls.real("RHO_EXCL");
  if (!(s.lineSearch.rhoMin < s.lineSearch.rhoMax)) {
    throw UserError(msg::make("SNL_10", {}, ls.locationOf("RHO_MIN")));
  }
}

} // namespace

// The catalogue gives NEWTON, CONVERGENCE and RECH_LINEAIRE's keywords their defaults: the
// validated tree holds them, so they are read without a fallback (tools/lint/or-fallbacks.py).
NewtonSettings readNewtonSettings(const KeywordTree& kw, const MechanicalSystem& system) {
  NewtonSettings s;
  if (kw.has("NEWTON")) {
    const KeywordTree& nw = kw.occurrences("NEWTON").front();
    s.tangentMatrix = nw.text("MATRICE") == "TANGENTE";
    s.reacIter = static_cast<int>(nw.integer("REAC_ITER"));
    s.reacIncr = static_cast<int>(nw.integer("REAC_INCR"));
    s.prediction = readPrediction(nw, s.tangentMatrix);
    if (s.prediction == Prediction::Computed) {
      s.computedDisplacement = computedDisplacement(nw, system);
    }
    s.symmetrizeTangent = nw.text("MATR_RIGI_SYME") == "OUI";
  }
  if (kw.has("CONVERGENCE")) {
    const KeywordTree& cv = kw.occurrences("CONVERGENCE").front();
    s.resiGlobRela = cv.realOr("RESI_GLOB_RELA", -1.0);
    s.resiGlobMaxi = cv.realOr("RESI_GLOB_MAXI", -1.0);
    // With the elastic matrix code_aster allows ITER_GLOB_ELAS iterations.
    s.iterGlobMaxi =
        static_cast<int>(s.tangentMatrix ? cv.integer("ITER_GLOB_MAXI") : cv.integer("ITER_GLOB_ELAS"));
    s.verif = cv.text("VERIF") == "AU_MOINS_UN" ? CriteriaCombination::AtLeastOne : CriteriaCombination::All;
  }
  readLineSearch(kw, s);
  return s;
}

std::vector<double> readInstants(const KeywordTree& inc, std::optional<double> initialTime,
                                 std::shared_ptr<const InstantList>& list) {
  auto c = inc.conceptValue("LIST_INST");
  std::vector<double> times;
  if (auto l = conceptData<RealList>(c)) {
    times = l->values;
  } else if (auto li = conceptData<InstantList>(c)) {
    times = li->instants;
    list = li;
  }
  auto numbered = [&](const char* name) {
    const auto k = inc.integer(name);
    if (k < 0 || k >= static_cast<std::int64_t>(times.size())) {
      throw UserError(
          msg::make("SNL_8", {{"name", name}, {"k", k}, {"times_count", static_cast<int>(times.size()) - 1}},
                    inc.locationOf(name)));
    }
    return times[static_cast<std::size_t>(k)];
  };
  const double first = times.empty() ? 0.0 : times.front();
  double start = inc.has("NUME_INST_INIT") ? numbered("NUME_INST_INIT")
                                           : inc.realOr("INST_INIT", initialTime.value_or(first));
  const double end = inc.has("NUME_INST_FIN") ? numbered("NUME_INST_FIN")
                                              : inc.realOr("INST_FIN", times.empty() ? 0.0 : times.back());
  // PRECISION is in the block of INST_INIT and INST_FIN; without them the instants of the list are
  // compared to the initial state's with code_aster's default relative precision.
  constexpr double instantPrecision = 1.0e-6;
  const double precision =
      inc.has("INST_INIT") || inc.has("INST_FIN") ? inc.real("PRECISION") : instantPrecision;
  auto near = [&](double a, double b) {
    return std::fabs(a - b) <= precision * std::max(std::fabs(b), 1.0e-300);
  };
  std::vector<double> out{start};
  for (double t : times) {
    if (t > start && !near(t, start) && (t < end || near(t, end))) {
      out.push_back(t);
    }
  }
  if (out.size() < 2) {
    throw UserError(msg::make("SNL_2", {}, inc.location()));
  }
  return out;
}

CutPolicy readCutPolicy(const InstantList* list) {
  CutPolicy p; // code_aster's default: ERREUR, DECOUPE, SUBD_PAS=4, SUBD_NIVEAU=3
  if (list == nullptr) {
    return p;
  }
  const FailurePolicy f = list->onError();
  p.subdivide = f.action == FailurePolicy::Action::Subdivide;
  p.subdivisions = f.subdivisions;
  p.maxLevel = f.maxLevel;
  p.minStep = f.minStep;
  return p;
}

std::optional<InitialResultStep> readInitialStep(const KeywordTree& kw,
                                                 const std::shared_ptr<Result>& reused) {
  if (kw.has("ETAT_INIT")) {
    const KeywordTree& e = kw.occurrences("ETAT_INIT").front();
    // DEPL, SIGM, VARI, STRX, NUME_DIDI: refused by the catalogue (non_implemente=).
    auto result = conceptData<Result>(e.conceptValue("EVOL_NOLI"));
    STELLA_ASSERT(result != nullptr, "ETAT_INIT/EVOL_NOLI holds no result");
    const ResultStep* step = nullptr;
    if (e.has("NUME_ORDRE")) {
      step = result->stepNumber(static_cast<int>(e.integer("NUME_ORDRE")));
    } else if (e.has("INST")) {
      step = result->stepAtTime(e.real("INST"), e.real("PRECISION"), e.text("CRITERE") == "ABSOLU");
    } else if (!result->steps.empty()) {
      step = &result->steps.back();
    }
    if (step == nullptr) {
      throw UserError(
          msg::make("SNL_9",
                    {{"name", e.conceptValue("EVOL_NOLI")->name},
                     {"has", e.has("NUME_ORDRE") ? fmt::format("NUME_ORDRE {}", e.integer("NUME_ORDRE"))
                                                 : fmt::format("INST {:g}", e.realOr("INST", 0.0))}},
                    e.location()));
    }
    return InitialResultStep{result, step};
  }
  if (reused && !reused->steps.empty()) {
    return InitialResultStep{reused, &reused->steps.back()};
  }
  return std::nullopt;
}

MechanicalState stateFromResultStep(const InitialResultStep& initial, const MechanicalSystem& system,
                                    const MechanicalState& zero, const SourceLocation& at) {
  const Model& model = system.model();
  if (initial.result->mesh.get() != model.mesh.get()) {
    throw UserError(msg::make("SNL_9.2", {}, at));
  }
  MechanicalState s = zero;
  s.time = initial.step->time;
  if (const Field* d = initial.step->field("DEPL")) {
    if (d->entityCount() != static_cast<std::size_t>(model.mesh->nodeCount()) ||
        d->componentCount() < static_cast<std::size_t>(model.components)) {
      throw UserError(msg::make("SNL_9.3", {}, at));
    }
    s.displacement = displacementVector(*d, system.dofs());
  }
  auto copyPoints = [&](const char* name, Field& target) {
    const Field* f = initial.step->field(name);
    if (f == nullptr) {
      return;
    }
    if (f->entityCount() != target.entityCount()) {
      throw UserError(msg::make(
          "SNL_9.4",
          {{"name", name}, {"entity_count", f->entityCount()}, {"entity_count_2", target.entityCount()}},
          at));
    }
    const std::size_t nc = std::min(f->componentCount(), target.componentCount());
    for (std::size_t p = 0; p < target.entityCount(); ++p) {
      for (std::size_t c = 0; c < nc; ++c) {
        target.value(p, c) = f->value(p, c);
      }
    }
  };
  copyPoints("SIEF_ELGA", s.points.stress);
  copyPoints("VARI_ELGA", s.points.internal);
  // The strains of the displacement (the behaviours integrate from them).
  PointState strains = zero.points;
  system.assembler().run(zero.displacement, s.displacement, zero.points, behaviour::Option::ResidualOnly,
                         {nullptr, nullptr, &strains});
  s.points.strain = strains.strain;
  return s;
}

} // namespace stella
