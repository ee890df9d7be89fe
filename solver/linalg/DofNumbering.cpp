// DOF numbering: physical DOFs node by node, then Lagrange multipliers.

#include "solver/linalg/DofNumbering.hpp"

#include <stdexcept>

namespace stella::linalg {

std::string_view componentName(Component c) {
  switch (c) {
  case Component::DX:
    return "DX";
  case Component::DY:
    return "DY";
  case Component::DZ:
    return "DZ";
  case Component::LAGR:
    return "LAGR";
  case Component::LAGS_C:
    return "LAGS_C";
  case Component::LAGS_F1:
    return "LAGS_F1";
  case Component::LAGS_F2:
    return "LAGS_F2";
  }
  return "?";
}

DofNumbering::DofNumbering(int nodeCount, int componentsPerNode, std::span<const bool> active)
    : components_(componentsPerNode), firstDof_(static_cast<std::size_t>(nodeCount), -1) {
  if (componentsPerNode < 1 || componentsPerNode > 3) {
    throw std::invalid_argument("DofNumbering: 1 to 3 components per node");
  }
  if (!active.empty() && static_cast<int>(active.size()) != nodeCount) {
    throw std::invalid_argument("DofNumbering: active flags size differs from node count");
  }
  for (int n = 0; n < nodeCount; ++n) {
    if (active.empty() || active[static_cast<std::size_t>(n)]) {
      firstDof_[static_cast<std::size_t>(n)] = physical_;
      for (int c = 0; c < components_; ++c) {
        info_.push_back({n, static_cast<Component>(c), static_cast<Component>(c)});
      }
      physical_ += components_;
    }
  }
}

int DofNumbering::addLagrange(Component kind, int node, Component constrained) {
  if (kind < Component::LAGR) {
    throw std::invalid_argument("DofNumbering::addLagrange: not a multiplier component");
  }
  info_.push_back({node, kind, constrained});
  return dofCount() - 1;
}

std::string DofNumbering::describeText(int equation, std::span<const std::string> nodeNames) const {
  const EquationInfo& i = describe(equation);
  std::string text;
  if (i.node >= 0) {
    text = i.node < static_cast<int>(nodeNames.size()) ? nodeNames[static_cast<std::size_t>(i.node)]
                                                       : "N" + std::to_string(i.node + 1);
    text += " ";
  }
  text += componentName(i.component);
  if (i.component == Component::LAGR) {
    text += " (on " + std::string(componentName(i.constrained)) + ")";
  }
  return text;
}

std::pair<std::string, std::string>
DofNumbering::explainSingularity(int equation, std::span<const std::string> nodeNames) const {
  if (equation < 0 || equation >= dofCount()) {
    return {"the stiffness matrix is singular: a rigid-body motion of the model is not blocked",
            "block every free motion with DDL_IMPO, or hold the free bodies with discrete springs "
            "(DIS_T / 2D_DIS_T on POI1 cells with small stiffnesses K_T_D_N), as section 4.4.2 of the "
            "contact notice advises"};
  }
  const EquationInfo& i = describe(equation);
  if (i.isLagrange()) {
    return {"the stiffness matrix is singular at the Lagrange multiplier " +
                describeText(equation, nodeNames) +
                ": this condition is redundant with another one (the same DOF imposed twice, or "
                "relations that are not independent)",
            "remove the duplicate condition (DDL_IMPO, LIAISON_*, or a contact zone that overlaps "
            "another condition)"};
  }
  return {"the stiffness matrix is singular: DOF " + std::string(componentName(i.component)) + " of node " +
              describeText(equation, nodeNames).substr(0, describeText(equation, nodeNames).find(' ')) +
              " is free (a rigid-body motion of the part holding this node is not blocked)",
          "block the motion (DDL_IMPO on that node or its group), or hold the body with discrete "
          "springs (DIS_T / 2D_DIS_T on POI1 cells with small stiffnesses K_T_D_N), as section 4.4.2 "
          "of the contact notice advises; a body held only by contact needs such springs until "
          "contact closes"};
}

} // namespace stella::linalg
