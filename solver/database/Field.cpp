#include "Field.hpp"

#include "interpreter/Diagnostics.hpp"

namespace stella {

Field Field::nodal(std::string quantity, std::vector<std::string> components, std::size_t nodeCount) {
  Field f;
  f.support_ = FieldSupport::Node;
  f.quantity_ = std::move(quantity);
  f.components_ = std::move(components);
  f.entities_ = nodeCount;
  f.values_.assign(nodeCount * f.components_.size(), 0.0);
  return f;
}

Field Field::perCell(std::string quantity, std::vector<std::string> components, std::size_t cellCount) {
  Field f = nodal(std::move(quantity), std::move(components), cellCount);
  f.support_ = FieldSupport::Cell;
  return f;
}

Field Field::perPoint(FieldSupport support, std::string quantity, std::vector<std::string> components,
                      const std::vector<int>& pointsPerCell) {
  STELLA_ASSERT(support == FieldSupport::GaussPoint || support == FieldSupport::CellNode,
                "perPoint is for Gauss-point and cell-node fields");
  Field f;
  f.support_ = support;
  f.quantity_ = std::move(quantity);
  f.components_ = std::move(components);
  f.offsets_.resize(pointsPerCell.size() + 1, 0);
  for (std::size_t c = 0; c < pointsPerCell.size(); ++c) {
    f.offsets_[c + 1] = f.offsets_[c] + static_cast<std::size_t>(pointsPerCell[c]);
  }
  f.entities_ = f.offsets_.back();
  f.values_.assign(f.entities_ * f.components_.size(), 0.0);
  return f;
}

std::optional<std::size_t> Field::componentIndex(const std::string& name) const {
  for (std::size_t i = 0; i < components_.size(); ++i) {
    if (components_[i] == name) {
      return i;
    }
  }
  return std::nullopt;
}

int Field::pointCount(std::size_t cell) const {
  return offsets_.empty() ? 0 : static_cast<int>(offsets_[cell + 1] - offsets_[cell]);
}

std::span<const double> Field::entity(std::size_t e) const {
  return std::span<const double>(values_).subspan(e * components_.size(), components_.size());
}

std::span<double> Field::entity(std::size_t e) {
  return std::span<double>(values_).subspan(e * components_.size(), components_.size());
}

void Field::markPartial() {
  defined_.assign(values_.size(), 0);
}

bool Field::defined(std::size_t entity, std::size_t component) const {
  return defined_.empty() || defined_[entity * components_.size() + component] != 0;
}

void Field::setDefined(std::size_t entity, std::size_t component, bool on) {
  if (defined_.empty()) {
    if (on) {
      return;
    }
    defined_.assign(values_.size(), 1);
  }
  defined_[entity * components_.size() + component] = on ? 1 : 0;
}

} // namespace stella
