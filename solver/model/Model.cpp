// Model: cell kinds and the node components of a mechanical model.

#include "solver/model/Model.hpp"

namespace stella {

Model::Model(std::shared_ptr<const Mesh> m) : mesh(std::move(m)) {
  cells.resize(static_cast<std::size_t>(mesh->cellCount()));
  activeNodes.assign(static_cast<std::size_t>(mesh->nodeCount()), false);
}

std::vector<CellId> Model::cellsOfKind(ElementKind k) const {
  std::vector<CellId> out;
  for (CellId c = 0; c < static_cast<CellId>(cells.size()); ++c) {
    if (cells[static_cast<std::size_t>(c)].kind == k) {
      out.push_back(c);
    }
  }
  return out;
}

std::string Model::componentName(int c) {
  static const char* names[] = {"DX", "DY", "DZ"};
  return names[c];
}

std::optional<int> Model::componentIndex(const std::string& name) const {
  for (int c = 0; c < components; ++c) {
    if (componentName(c) == name) {
      return c;
    }
  }
  return std::nullopt;
}

std::vector<std::string> Model::componentNames() const {
  std::vector<std::string> out;
  for (int c = 0; c < components; ++c) {
    out.push_back(componentName(c));
  }
  return out;
}

} // namespace stella
