// STAT_NON_LINE: nonlinear quasi-static analysis by Newton over the instants of INCREMENT,
// COMPORTEMENT ELAS / VMIS_ISOT_LINE per group, results DEPL, SIEF_ELGA, VARI_ELGA per step in an
// evol_noli (NUME_ORDRE 0 = the initial state). A step that does not converge stops the run with
// <S>_NO_CONVERGENCE, keeping every converged step. Step cutting (DEFI_LIST_INST ECHEC),
// ETAT_INIT, ARCHIVAGE selections, contact and line search are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "solver/contact/ContactStepConstraint.hpp"
#include "solver/database/Result.hpp"
#include "solver/functions/InstantList.hpp"
#include "solver/model/Selection.hpp"
#include "solver/nonlinear/CommandInputs.hpp"
#include "solver/nonlinear/NewtonDriver.hpp"
#include "solver/nonlinear/ResultFields.hpp"
#include "solver/nonlinear/ResultLoads.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

void refuseAbsent(const KeywordTree& kw) {
  for (const char* k : {"CARA_ELEM", "PILOTAGE", "ETAT_INIT", "RESULTAT"}) {
    const FactorKeyword* f = kw.factor(k);
    if ((f != nullptr && !f->defaulted) || (f == nullptr && kw.simple(k) != nullptr)) {
      throw UserError(Diagnostic::fatal("SNL_1", fmt::format("STAT_NON_LINE {} is not implemented yet", k),
                                        kw.locationOf(k)));
    }
  }
  if (kw.has("RECH_LINEAIRE") && !kw.factor("RECH_LINEAIRE")->defaulted) {
    throw UserError(Diagnostic::fatal("SNL_1", "STAT_NON_LINE RECH_LINEAIRE is not implemented yet",
                                      kw.locationOf("RECH_LINEAIRE")));
  }
}

std::vector<std::string> relationsOf(const KeywordTree& kw, const Model& model) {
  std::vector<std::string> relations(model.cells.size(), "ELAS");
  for (const KeywordTree& occ : kw.occurrences("COMPORTEMENT")) {
    const std::string deformation = occ.textOr("DEFORMATION", "PETIT");
    if (deformation != "PETIT") {
      throw UserError(Diagnostic::fatal("COMPOR_2",
                                        fmt::format("DEFORMATION='{}' is not implemented yet", deformation),
                                        occ.locationOf("DEFORMATION"))
                          .withNote("available: DEFORMATION='PETIT' (small strains)"));
    }
    const std::string relation = occ.textOr("RELATION", "ELAS");
    for (CellId c : selectCells(*model.mesh, occ)) {
      relations[static_cast<std::size_t>(c)] = relation;
    }
  }
  return relations;
}

std::vector<double> instantsOf(const KeywordTree& inc, std::shared_ptr<const InstantList>& policy) {
  auto c = inc.conceptValue("LIST_INST");
  std::vector<double> times;
  if (auto l = conceptData<RealList>(c)) {
    times = l->values;
  } else if (auto li = conceptData<InstantList>(c)) {
    times = li->instants;
    policy = li;
  }
  const double start = inc.realOr("INST_INIT", times.empty() ? 0.0 : times.front());
  const double end = inc.realOr("INST_FIN", times.empty() ? 0.0 : times.back());
  const double eps = 1.0e-9 * std::max(1.0, std::fabs(end));
  std::vector<double> out;
  for (double t : times) {
    if (t >= start - eps && t <= end + eps) {
      out.push_back(t);
    }
  }
  if (out.size() < 2) {
    throw UserError(Diagnostic::fatal("SNL_2", "INCREMENT leaves fewer than two instants: no step to compute",
                                      inc.location()));
  }
  return out;
}

NewtonSettings settingsOf(const KeywordTree& kw) {
  NewtonSettings s;
  if (kw.has("NEWTON")) {
    const KeywordTree& nw = kw.occurrences("NEWTON").front();
    s.tangentMatrix = nw.textOr("MATRICE", "TANGENTE") == "TANGENTE";
    s.reacIter = static_cast<int>(nw.integerOr("REAC_ITER", 1));
    const std::string prediction = nw.textOr("PREDICTION", s.tangentMatrix ? "TANGENTE" : "ELASTIQUE");
    if (prediction != "TANGENTE" && prediction != "ELASTIQUE") {
      throw UserError(Diagnostic::fatal("SNL_1",
                                        fmt::format("PREDICTION='{}' is not implemented yet", prediction),
                                        nw.locationOf("PREDICTION")));
    }
    s.elasticPrediction = prediction == "ELASTIQUE";
  }
  if (kw.has("CONVERGENCE")) {
    const KeywordTree& cv = kw.occurrences("CONVERGENCE").front();
    s.resiGlobRela = cv.realOr("RESI_GLOB_RELA", -1.0);
    s.resiGlobMaxi = cv.realOr("RESI_GLOB_MAXI", -1.0);
    s.iterGlobMaxi = static_cast<int>(cv.integerOr("ITER_GLOB_MAXI", 10));
  }
  return s;
}

void store(Result& result, const MechanicalState& s, const MechanicalSystem& system,
           const StepConstraint* constraint) {
  ResultStep& step = result.addStep(s.time, 0);
  storeMechanicalFields(step, system.model(), system.dofs(), s.displacement, s.points, true, true);
  if (constraint != nullptr) {
    constraint->store(step);
  }
}

Value runStatNonLine(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  refuseAbsent(kw);
  auto model = readModel(kw);
  auto materials = readMaterialField(kw, *model);
  MechanicalSystem system(model, materials, readExcitations(kw), relationsOf(kw, *model), call.location);
  system.solver().setOptions(readSolverOptions(kw));
  std::shared_ptr<const InstantList> policy;
  const auto times = instantsOf(kw.occurrences("INCREMENT").front(), policy);
  NewtonSettings settings = settingsOf(kw);
  auto& msg = call.session.message();
  const std::unique_ptr<StepConstraint> constraint = makeContactConstraint(kw, system);
  const bool linear = system.behaviours().allLinear();
  msg << fmt::format(
      "   effects: {}, {} load(s), {} {} factorisation, {} Lagrange multiplier(s), {}\n",
      linear ? "elasticity (no return mapping)"
             : fmt::format("{} (return mapping)", fmt::join(system.behaviours().relationNames(), ", ")),
      system.excitations().size(), system.behaviours().allSymmetric() ? "symmetric" : "unsymmetric",
      settings.tangentMatrix ? "tangent" : "elastic", system.relationCount(),
      constraint != nullptr ? constraint->effects() : std::string("no contact"));
  auto result = std::make_shared<Result>();
  result->type = "evol_noli";
  result->mesh = model->mesh;
  result->model = std::const_pointer_cast<Model>(model);
  result->material = std::const_pointer_cast<MaterialField>(materials);
  NewtonDriver driver(system, settings, msg);
  driver.setConstraint(constraint.get());
  MechanicalState state = driver.initialState(times.front());
  store(*result, state, system, constraint.get());
  rememberLoads(result, system.excitations());
  Value made = call.makeConcept(result);
  for (std::size_t i = 1; i < times.size(); ++i) {
    MechanicalState next;
    const StepOutcome o = driver.step(state, times[i], next);
    if (!o.converged) {
      const std::string kept = fmt::format("{}: {} converged step(s) kept, up to INST {}", call.resultName,
                                           result->steps.size() - 1, state.time);
      call.session.noteKeptResult(kept);
      throw UserError(
          Diagnostic::noConvergence(
              "SNL_3",
              fmt::format("Newton did not converge at INST {} ({}; RESI_GLOB_RELA = {:.3e} after {} "
                          "iterations); {}",
                          times[i],
                          o.integrationFailed ? "the behaviour integration failed" : "residual too large",
                          o.resiRela, o.iterations, kept),
              call.location)
              .withNote("step cutting (DEFI_LIST_INST ECHEC) is not implemented yet: refine the list of "
                        "instants, or raise ITER_GLOB_MAXI"));
    }
    state = std::move(next);
    if (constraint != nullptr) {
      constraint->reportStep(msg);
    }
    store(*result, state, system, constraint.get());
    msg << fmt::format("   step {} INST {} converged in {} iteration(s), RESI_GLOB_RELA = {:.3e}\n", i,
                       times[i], o.iterations, o.resiRela);
  }
  msg << fmt::format("   linear solver: {}, {} factorisation(s)\n", system.solver().backendName(),
                     system.solver().factorizations());
  return made;
}

} // namespace

STELLA_OPERATOR("STAT_NON_LINE", runStatNonLine);

} // namespace stella
