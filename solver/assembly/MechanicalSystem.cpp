// MechanicalSystem: equations, constraints and eliminated DOFs of the EXCIT loads.

#include "solver/assembly/MechanicalSystem.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/assembly/ExternalForces.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

void checkModel(const Model* loadModel, const Model& model, const SourceLocation& at) {
  if (loadModel != &model) {
    throw UserError(msg::make("LOAD_8", {}, at));
  }
}

} // namespace

MechanicalSystem::MechanicalSystem(std::shared_ptr<const Model> model,
                                   std::shared_ptr<const MaterialField> materials,
                                   std::vector<Excitation> excitations,
                                   const std::vector<std::string>& relations, const SourceLocation& at,
                                   std::shared_ptr<const ElementCharacteristics> cara,
                                   std::vector<fem::StrainMeasure> strains)
    : model_(std::move(model)), materials_(std::move(materials)), cara_(std::move(cara)),
      excitations_(std::move(excitations)), dofs_(*model_),
      behaviours_(*model_, *materials_, relations, at, std::move(strains)),
      assembler_(*model_, dofs_, behaviours_, cara_.get()) {
  if (cara_ && cara_->model.get() != model_.get()) {
    throw UserError(msg::make("CARA_6", {}, at));
  }
  checkDiscreteElementsCovered(*model_, cara_.get(), at);
  std::vector<ConstraintRow> rows;
  std::vector<bool> eliminated(static_cast<std::size_t>(dofs_.physicalCount()), false);
  for (std::size_t e = 0; e < excitations_.size(); ++e) {
    const auto& ex = excitations_[e];
    if (ex.load) {
      checkModel(ex.load->model.get(), *model_, at);
      dofs_.addRelations(ex.load->relations);
      for (const auto& r : ex.load->relations) {
        ConstraintRow row;
        for (const auto& t : r.terms) {
          row.terms.emplace_back(dofs_.dof(t.node, t.component), t.coefficient);
        }
        rows.push_back(std::move(row));
        relationExcitation_.push_back(static_cast<int>(e));
      }
    }
    if (ex.kinematic) {
      checkModel(ex.kinematic->model.get(), *model_, at);
      for (const auto& d : ex.kinematic->imposed) {
        const int eq = dofs_.dof(d.node, d.component);
        eliminated[static_cast<std::size_t>(eq)] = true;
        eliminated_.emplace_back(eq, static_cast<int>(e), d.value);
      }
    }
  }
  solver_ = std::make_unique<SaddleSolver>(dofs_, *model_->mesh, std::move(rows), std::move(eliminated));
}

Eigen::VectorXd MechanicalSystem::externalForces(double time) {
  return stella::externalForces(excitations_, time, dofs_, materials_.get(), forceCache_);
}

Eigen::VectorXd MechanicalSystem::relationValues(double time) const {
  Eigen::VectorXd g(dofs_.lagrangeCount());
  for (int r = 0; r < dofs_.lagrangeCount(); ++r) {
    g(r) = excitations_[static_cast<std::size_t>(relationExcitation_[static_cast<std::size_t>(r)])].factor(
               time) *
           dofs_.relation(r).value;
  }
  return g;
}

Eigen::VectorXd MechanicalSystem::eliminatedValues(double time) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(dofs_.physicalCount());
  for (const auto& [eq, e, value] : eliminated_) {
    v(eq) = excitations_[static_cast<std::size_t>(e)].factor(time) * value;
  }
  return v;
}

Eigen::SparseMatrix<double> MechanicalSystem::matrix(std::vector<Eigen::Triplet<double>>& triplets) const {
  Eigen::SparseMatrix<double> k(dofs_.physicalCount(), dofs_.physicalCount());
  k.setFromTriplets(triplets.begin(), triplets.end());
  k.makeCompressed();
  return k;
}

} // namespace stella

namespace stella {

StiffnessMatrix& MechanicalSystem::stiffness(bool symmetric) {
  auto& k = stiffness_[symmetric ? 0 : 1];
  if (!k) {
    PhaseClock clock(phases_.numbering);
    k = std::make_unique<StiffnessMatrix>(dofs_, *model_->mesh, assembler_.cells(),
                                          symmetric ? linalg::Storage::Upper : linalg::Storage::Full);
  }
  k->setZero();
  return *k;
}

PhaseTimes MechanicalSystem::phaseTimes() const {
  PhaseTimes t = phases_;
  const SaddleSolver::Timings& s = solver_->timings();
  t.factorisation = s.bordering + s.analysis + s.factorisation;
  t.solve = s.solve;
  return t;
}

} // namespace stella
