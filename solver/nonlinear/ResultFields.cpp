// ResultFields: vectors and states -> fields of a result step.

#include "solver/nonlinear/ResultFields.hpp"

namespace stella {

std::shared_ptr<Field> nodalField(const Model& model, const DofMap& dofs, const Eigen::VectorXd& v,
                                  const std::string& quantity) {
  const auto nodes = static_cast<std::size_t>(model.mesh->nodeCount());
  auto f = std::make_shared<Field>(Field::nodal(quantity, model.componentNames(), nodes));
  bool partial = false;
  for (std::size_t n = 0; n < nodes; ++n) {
    partial = partial || !model.activeNodes[n];
  }
  if (partial) {
    f->markPartial();
  }
  for (NodeId n = 0; n < static_cast<NodeId>(nodes); ++n) {
    if (!model.nodeActive(n)) {
      continue;
    }
    for (int c = 0; c < model.components; ++c) {
      f->value(static_cast<std::size_t>(n), static_cast<std::size_t>(c)) = v(dofs.dof(n, c));
      if (partial) {
        f->setDefined(static_cast<std::size_t>(n), static_cast<std::size_t>(c));
      }
    }
  }
  return f;
}

void storeMechanicalFields(ResultStep& step, const Model& model, const DofMap& dofs, const Eigen::VectorXd& u,
                           const PointState& state, bool withStress, bool withVariables) {
  step.fields["DEPL"] = nodalField(model, dofs, u, "DEPL_R");
  if (withStress) {
    step.fields["SIEF_ELGA"] = std::make_shared<Field>(state.stress);
  }
  if (withVariables) {
    step.fields["VARI_ELGA"] = std::make_shared<Field>(state.internal);
  }
}

Eigen::VectorXd displacementVector(const Field& depl, const DofMap& dofs) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs.physicalCount());
  for (int i = 0; i < dofs.physicalCount(); ++i) {
    u(i) = depl.value(static_cast<std::size_t>(dofs.node(i)), static_cast<std::size_t>(dofs.component(i)));
  }
  return u;
}

} // namespace stella
