// MECA_STATIQUE: linear static analysis, one solve per instant (INST, LIST_INST, default 0),
// results DEPL and SIEF_ELGA in an evol_elas from NUME_ORDRE 1.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/functions/InstantList.hpp"
#include "solver/inputs/CommandInputs.hpp"
#include "solver/inputs/ElementCharacteristicsReader.hpp"
#include "solver/nonlinear/ElasticSolve.hpp"
#include "solver/nonlinear/ResultFields.hpp"
#include "solver/nonlinear/ResultLoads.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <chrono>
#include <fmt/format.h>

namespace stella {

namespace {

std::vector<double> instants(const KeywordTree& kw) {
  std::vector<double> times;
  if (kw.has("INST")) {
    times = kw.reals("INST");
  } else if (kw.has("LIST_INST")) {
    auto c = kw.conceptValue("LIST_INST");
    if (auto l = conceptData<RealList>(c)) {
      times = l->values;
    } else if (auto li = conceptData<InstantList>(c)) {
      times = li->instants;
    }
    if (kw.has("INST_FIN")) {
      const double end = kw.real("INST_FIN");
      std::erase_if(times, [&](double t) { return t > end * (1.0 + 1.0e-12) + 1.0e-300; });
    }
  } else {
    times = {0.0};
  }
  if (times.empty()) {
    throw UserError(msg::make("STAT_1", {}, kw.location()));
  }
  return times;
}

Value runMecaStatique(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  auto model = readModel(kw);
  auto materials = readMaterialField(kw, *model);
  auto excitations = readExcitations(kw);
  std::vector<std::string> relations(model->cells.size(), "ELAS");
  auto cara = readCaraElem(kw);
  const auto numberingStart = std::chrono::steady_clock::now();
  MechanicalSystem system(model, materials, excitations, relations, call.location, cara);
  system.phases().numbering +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - numberingStart).count();
  system.solver().setOptions(readSolverOptions(kw));
  const bool withStress = kw.text("OPTION") == "SIEF_ELGA";
  auto& msg = call.session.message();
  msg << fmt::format("   equations: {} ({} displacement DOFs, {} Lagrange multipliers)\n",
                     system.dofs().size(), system.dofs().physicalCount(), system.dofs().lagrangeCount());
  msg << fmt::format(
      "   effects: linear elasticity (no return mapping), {} load(s), {} discrete spring(s), one "
      "factorisation for every instant\n",
      excitations.size(), cara ? cara->springs.size() : 0);

  std::shared_ptr<Result> result;
  if (call.reused) {
    result = conceptData<Result>(call.reused);
  }
  if (!result) {
    result = std::make_shared<Result>();
    result->type = "evol_elas";
    result->mesh = model->mesh;
    result->model = std::const_pointer_cast<Model>(model);
    result->material = std::const_pointer_cast<MaterialField>(materials);
  }
  ElasticSolve solver(system);
  bool first = true;
  for (double t : instants(kw)) {
    StaticSolution s = solver.solve(t, withStress);
    if (first) {
      const int bordered = system.solver().borderedRelationCount();
      msg << fmt::format("   linear solver: {} ({} matrix, factorised once; {} single-DOF relation(s) "
                         "eliminated, {} multiplier(s) in the matrix)\n",
                         system.solver().backendName(),
                         bordered > 0 ? "symmetric indefinite" : "symmetric positive definite",
                         system.dofs().lagrangeCount() - bordered, bordered);
      if (system.solver().lastIterations() > 0) {
        msg << fmt::format("   iterative solver: {} iteration(s) for the first solve; peak memory of the "
                           "solver's process: {:.0f} MB\n",
                           system.solver().lastIterations(), system.solver().workerPeakMegabytes());
      }
      first = false;
    }
    PhaseClock clock(system.phases().post);
    ResultStep& step = result->addStep(t, 1);
    storeMechanicalFields(step, *model, system.dofs(), s.displacement, s.state, withStress, false);
    msg << fmt::format("   stored NUME_ORDRE {} at INST {}: max |u| = {:.6e}\n", step.number, t,
                       s.displacement.size() ? s.displacement.cwiseAbs().maxCoeff() : 0.0);
  }
  if (const std::string summary = system.solver().backendSummary(); !summary.empty()) {
    msg << "   solver summary: " << summary << "\n";
  }
  msg << formatPhases(system.phaseTimes(), system.solver().timings().analyses, system.dofs().size());
  rememberLoads(result, excitations);
  rememberCharacteristics(result, cara);
  return call.makeConcept(result);
}

} // namespace

STELLA_OPERATOR("MECA_STATIQUE", runMecaStatique);

} // namespace stella
