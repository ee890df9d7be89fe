// CommandInputs: EXCIT, MODELE, CHAM_MATER and SOLVEUR of the static drivers.

#include "solver/inputs/CommandInputs.hpp"
#include "solver/linalg/MumpsOrderings.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/model/RepeatedConditions.hpp"

#include <fmt/format.h>

namespace stella {

std::vector<Excitation> readExcitations(const KeywordTree& keywords) {
  std::vector<Excitation> out;
  std::vector<ExcitedLoad> loads;
  for (const KeywordTree& occ : keywords.occurrences("EXCIT")) {
    Excitation e;
    auto charge = occ.conceptValue("CHARGE");
    e.load = conceptData<MechanicalLoad>(charge);
    e.kinematic = conceptData<KinematicLoad>(charge);
    if (!e.load && !e.kinematic) {
      throw UserError(msg::make("LOAD_9", {{"name", charge->name}}, occ.locationOf("CHARGE")));
    }
    if (occ.has("FONC_MULT")) {
      auto f = occ.conceptValue("FONC_MULT");
      e.multiplier = conceptData<RealFunction>(f);
      if (!e.multiplier || e.multiplier->parameters().size() != 1) {
        throw UserError(msg::make("LOAD_10", {{"name", f->name}}, occ.locationOf("FONC_MULT")));
      }
    }
    if (occ.text("TYPE_CHARGE") != "FIXE_CSTE") {
      throw UserError(
          msg::make("LOAD_4", {{"text", occ.text("TYPE_CHARGE")}}, occ.locationOf("TYPE_CHARGE")));
    }
    loads.push_back({e.load, e.kinematic, e.multiplier.get(), charge->name, occ.locationOf("CHARGE")});
    out.push_back(std::move(e));
  }
  // A DOF imposed by several dualised conditions keeps one multiplier (LOAD_11 on a conflict).
  const auto merged = mergeRepeatedConditions(loads);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].load = merged[i];
  }
  return out;
}

std::shared_ptr<const Model> readModel(const KeywordTree& keywords) {
  auto model = conceptData<Model>(keywords.conceptValue("MODELE"));
  STELLA_ASSERT(model != nullptr, "MODELE holds no model");
  return model;
}

std::shared_ptr<const MaterialField> readMaterialField(const KeywordTree& keywords, const Model& model) {
  if (!keywords.has("CHAM_MATER")) {
    throw UserError(msg::make("MATER_9", {}, keywords.location()));
  }
  auto field = conceptData<MaterialField>(keywords.conceptValue("CHAM_MATER"));
  STELLA_ASSERT(field != nullptr, "CHAM_MATER holds no material field");
  if (field->mesh != model.mesh) {
    throw UserError(msg::make("MATER_9.2", {}, keywords.locationOf("CHAM_MATER")));
  }
  return field;
}

namespace {

// MUMPS's own options (METHODE='MUMPS', and LOW_RANK_SEUIL / GESTION_MEMOIRE of GCPC's LDLT_SP
// preconditioner); the catalogue refuses the values not implemented.
linalg::MumpsControls readMumpsControls(const KeywordTree& s, linalg::SolverMethod method) {
  linalg::MumpsControls c;
  if (s.has("GESTION_MEMOIRE")) {
    c.memory = s.text("GESTION_MEMOIRE");
  }
  if (s.has("ACCELERATION")) {
    c.acceleration = s.text("ACCELERATION");
  }
  if (s.has("PRETRAITEMENTS")) {
    c.preprocessing = s.text("PRETRAITEMENTS");
  }
  if (s.has("POSTTRAITEMENTS")) {
    c.postprocessing = s.text("POSTTRAITEMENTS");
  }
  if (method == linalg::SolverMethod::Mumps && s.has("RESI_RELA")) {
    c.backwardErrorLimit = s.real("RESI_RELA");
  }
  if (s.has("LOW_RANK_SEUIL")) { // only under ACCELERATION='LR'/'LR+' (MUMPS) or LDLT_SP (GCPC)
    c.lowRankThreshold = s.real("LOW_RANK_SEUIL");
    if (method == linalg::SolverMethod::Gcpc && c.lowRankThreshold > 0.0) {
      c.acceleration = "LR"; // LDLT_SP: a threshold is the request for a low-rank preconditioner
    }
  }
  return c;
}

} // namespace

linalg::SolverOptions readSolverOptions(const KeywordTree& keywords) {
  linalg::SolverOptions o;
  if (!keywords.has("SOLVEUR")) {
    return o;
  }
  const KeywordTree& s = keywords.occurrences("SOLVEUR").front();
  const std::string method = s.text("METHODE");
  auto m = linalg::solverMethodFromName(method);
  if (!m) {
    throw UserError(msg::make("SOLVE_5", {{"method", method}}, s.locationOf("METHODE")));
  }
  if (*m == linalg::SolverMethod::Petsc && !linalg::petscAvailable()) {
    // RUN_8, an id about the machine: the study is valid, this build lacks the PETSc worker
    throw UserError(msg::make("RUN_8", {}, s.locationOf("METHODE")));
  }
  o.method = *m;
  o.renumbering = s.textOr("RENUM", o.renumbering);
  if (o.method == linalg::SolverMethod::Mumps && !linalg::mumpsOrderingAvailable(o.renumbering)) {
    // RUN_9, about the machine like RUN_8: the study is valid, this build's MUMPS lacks the ordering
    throw UserError(msg::make("RUN_9", {{"renum", o.renumbering}}, s.locationOf("RENUM")));
  }
  o.nprec = static_cast<int>(s.integerOr("NPREC", o.nprec));
  o.pivotPercent = static_cast<double>(s.integerOr("PCENT_PIVOT", static_cast<std::int64_t>(o.pivotPercent)));
  const bool iterative = o.method == linalg::SolverMethod::Gcpc || o.method == linalg::SolverMethod::Petsc;
  if (!iterative) { // STOP_SINGULIER: the direct solvers' blocks only
    o.stopIfSingular = s.text("STOP_SINGULIER") == "OUI";
  }
  if (iterative && s.has("RESI_RELA") && s.real("RESI_RELA") > 0.0) { // MUMPS's: MumpsControls
    o.relativeResidual = s.real("RESI_RELA");
  }
  if (s.has("NMAX_ITER")) {
    o.maxIterations = static_cast<int>(s.integer("NMAX_ITER"));
  }
  if (s.has("PRE_COND")) { // GCPC, PETSC
    o.preconditioner = s.text("PRE_COND");
  }
  if (s.has("ALGORITHME")) { // PETSC
    o.algorithm = s.text("ALGORITHME");
  }
  if (*m == linalg::SolverMethod::Petsc) {
    if (s.has("OPTION_PETSC")) {
      o.petscOptions = s.text("OPTION_PETSC");
    }
    if (s.has("NIVE_REMPLISSAGE")) { // LDLT_INC
      o.fillLevel = static_cast<int>(s.integer("NIVE_REMPLISSAGE"));
      o.fill = s.real("REMPLISSAGE");
    }
  }
  if (s.has("REAC_PRECOND")) { // GCPC, LDLT_SP
    o.preconditionerReuseIterations = static_cast<int>(s.integer("REAC_PRECOND"));
  }
  o.mumps = readMumpsControls(s, o.method);
  return o;
}

} // namespace stella
