// CommandInputs: EXCIT, MODELE, CHAM_MATER and SOLVEUR of the static drivers.

#include "solver/nonlinear/CommandInputs.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <fmt/format.h>

namespace stella {

std::vector<Excitation> readExcitations(const KeywordTree& keywords) {
  std::vector<Excitation> out;
  for (const KeywordTree& occ : keywords.occurrences("EXCIT")) {
    Excitation e;
    auto charge = occ.conceptValue("CHARGE");
    e.load = conceptData<MechanicalLoad>(charge);
    e.kinematic = conceptData<KinematicLoad>(charge);
    if (!e.load && !e.kinematic) {
      throw UserError(Diagnostic::fatal("LOAD_9",
                                        fmt::format("CHARGE={} is not a mechanical load", charge->name),
                                        occ.locationOf("CHARGE"))
                          .withNote("contact definitions (DEFI_CONTACT) go in CONTACT=, not in EXCIT"));
    }
    if (occ.has("FONC_MULT")) {
      auto f = occ.conceptValue("FONC_MULT");
      e.multiplier = conceptData<RealFunction>(f);
      if (!e.multiplier || e.multiplier->parameters().size() != 1) {
        throw UserError(Diagnostic::fatal(
            "LOAD_10", fmt::format("FONC_MULT={} must be a function of one parameter (INST)", f->name),
            occ.locationOf("FONC_MULT")));
      }
    }
    if (occ.textOr("TYPE_CHARGE", "FIXE_CSTE") != "FIXE_CSTE") {
      throw UserError(Diagnostic::fatal(
          "LOAD_4", fmt::format("TYPE_CHARGE='{}' is not implemented yet", occ.text("TYPE_CHARGE")),
          occ.locationOf("TYPE_CHARGE")));
    }
    out.push_back(std::move(e));
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
    throw UserError(Diagnostic::fatal("MATER_9", "CHAM_MATER is missing: the model's cells need a material",
                                      keywords.location())
                        .withNote("build one with AFFE_MATERIAU and pass CHAM_MATER=..."));
  }
  auto field = conceptData<MaterialField>(keywords.conceptValue("CHAM_MATER"));
  STELLA_ASSERT(field != nullptr, "CHAM_MATER holds no material field");
  if (field->mesh != model.mesh) {
    throw UserError(Diagnostic::fatal("MATER_9", "CHAM_MATER was built on another mesh than the model's",
                                      keywords.locationOf("CHAM_MATER")));
  }
  return field;
}

std::string linearSolverDescription(const KeywordTree& keywords) {
  std::string method = "MUMPS";
  if (keywords.has("SOLVEUR")) {
    method = keywords.occurrences("SOLVEUR").front().textOr("METHODE", "MUMPS");
  }
  if (method == "PETSC") {
    throw UserError(Diagnostic::fatal("SOLVE_5", "SOLVEUR METHODE='PETSC' is not implemented yet",
                                      keywords.locationOf("SOLVEUR"))
                        .withNote("use METHODE='MUMPS' (the default)"));
  }
  return fmt::format(
      "SOLVEUR METHODE='{}': direct LU with partial pivoting (Eigen SparseLU, COLAMD ordering) on the "
      "system bordered by the Lagrange multipliers",
      method);
}

} // namespace stella
