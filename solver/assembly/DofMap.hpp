#pragma once
// The equations of a mechanical system: the displacement components of the model's nodes
// (DX, DY[, DZ], consecutive per node) followed by one Lagrange multiplier per dualised linear
// relation (DDL_IMPO, LIAISON_DDL...; contact multipliers will be appended the same way).
// Every equation can be described in words, so that solver errors name the node and DOF.

#include "solver/model/MechanicalLoad.hpp"
#include "solver/model/Model.hpp"

#include <string>
#include <vector>

namespace stella {

class DofMap {
public:
  explicit DofMap(const Model& model);

  int components() const { return components_; }
  int physicalCount() const { return physical_; }
  int lagrangeCount() const { return static_cast<int>(relations_.size()); }
  int size() const { return physical_ + lagrangeCount(); }
  // Equation of component c of a node, -1 if the node carries no DOF.
  int dof(NodeId n, int c) const {
    const int f = first_[static_cast<std::size_t>(n)];
    return f < 0 ? -1 : f + c;
  }
  NodeId node(int equation) const { return nodeOf_[static_cast<std::size_t>(equation / components_)]; }
  int component(int equation) const { return equation % components_; }

  // Appends one multiplier per relation; returns the first multiplier's equation.
  int addRelations(const std::vector<LinearRelation>& relations);
  const LinearRelation& relation(int multiplier) const {
    return *relations_[static_cast<std::size_t>(multiplier)];
  }

  // "node N12, component DY" or "Lagrange multiplier of DDL_IMPO on N3 DX".
  std::string describe(int equation, const Mesh& mesh) const;

private:
  int components_;
  int physical_ = 0;
  std::vector<int> first_;     // per mesh node
  std::vector<NodeId> nodeOf_; // per DOF block
  std::vector<const LinearRelation*> relations_;
};

} // namespace stella
