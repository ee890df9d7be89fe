#pragma once
// Numbering of the unknowns (NUME_DDL): physical displacement components of the model's nodes
// (DX, DY[, DZ], node by node, consecutive per node) followed by Lagrange multipliers (LAGR for
// dualised DDL_IMPO and linear relations, LAGS_C / LAGS_F1 / LAGS_F2 for contact and friction).
// Every equation can be described as (node, component) so that errors such as a singular
// stiffness name the node and DOF.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stella::linalg {

enum class Component : std::uint8_t { DX, DY, DZ, LAGR, LAGS_C, LAGS_F1, LAGS_F2 };

std::string_view componentName(Component c);

struct EquationInfo {
  int node = -1; // node the DOF belongs to / the constraint acts on (-1: none)
  Component component = Component::DX;
  Component constrained = Component::DX; // for LAGR: the component the multiplier constrains
  bool isLagrange() const { return component >= Component::LAGR; }
};

class DofNumbering {
public:
  // `componentsPerNode` = 2 (DX, DY) or 3 (DX, DY, DZ); only nodes with active[n] get DOFs
  // (an empty span makes every node active).
  DofNumbering(int nodeCount, int componentsPerNode, std::span<const bool> active = {});

  int componentsPerNode() const { return components_; }
  int nodeCount() const { return static_cast<int>(firstDof_.size()); }
  int physicalDofCount() const { return physical_; }
  int dofCount() const { return static_cast<int>(info_.size()); }
  // Equation of component c (0 = DX...) of a node, or -1 if the node has no DOF.
  int dof(int node, int c) const {
    const int f = firstDof_[static_cast<std::size_t>(node)];
    return f < 0 ? -1 : f + c;
  }
  int firstDof(int node) const { return firstDof_[static_cast<std::size_t>(node)]; }

  // Appends a Lagrange multiplier; returns its equation number.
  int addLagrange(Component kind, int node = -1, Component constrained = Component::DX);

  const EquationInfo& describe(int equation) const { return info_[static_cast<std::size_t>(equation)]; }
  // "N12 DY" style text, with 1-based node numbers unless names are given.
  std::string describeText(int equation, std::span<const std::string> nodeNames = {}) const;

  // The words of a singular-stiffness error at `equation` (STOP_SINGULIER): what is free and
  // what to do, for the operator to put in a UserError. Returns {message, note}.
  std::pair<std::string, std::string> explainSingularity(int equation,
                                                         std::span<const std::string> nodeNames = {}) const;

private:
  int components_;
  int physical_ = 0;
  std::vector<int> firstDof_;
  std::vector<EquationInfo> info_;
};

} // namespace stella::linalg
