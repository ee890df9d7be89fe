// DofMap: physical DOFs of the active nodes, then Lagrange multipliers.

#include "solver/assembly/DofMap.hpp"

#include <fmt/format.h>

namespace stella {

DofMap::DofMap(const Model& model) : components_(model.components) {
  first_.assign(model.activeNodes.size(), -1);
  for (std::size_t n = 0; n < model.activeNodes.size(); ++n) {
    if (model.activeNodes[n]) {
      first_[n] = physical_;
      nodeOf_.push_back(static_cast<NodeId>(n));
      physical_ += components_;
    }
  }
}

int DofMap::addRelations(const std::vector<LinearRelation>& relations) {
  const int first = size();
  for (const auto& r : relations) {
    relations_.push_back(&r);
  }
  return first;
}

std::string DofMap::describe(int equation, const Mesh& mesh) const {
  if (equation < physical_) {
    return fmt::format("node {}, component {}", mesh.nodeName(node(equation)),
                       Model::componentName(component(equation)));
  }
  const LinearRelation& r = relation(equation - physical_);
  std::string terms;
  for (const auto& t : r.terms) {
    terms += fmt::format("{}{} {}", terms.empty() ? "" : " + ", mesh.nodeName(t.node),
                         Model::componentName(t.component));
  }
  return fmt::format("Lagrange multiplier of {} on {}", r.origin, terms);
}

} // namespace stella
