#pragma once
// A field of the result database (code_aster's champ): named components (DX, DY, LAGS_C...)
// valued on the nodes (CHAM_NO: DEPL, SIEF_NOEU, CONT_NOEU), on the cells (CONT_ELEM), at the
// Gauss points of each cell (ELGA: SIEF_ELGA, VARI_ELGA) or at the nodes of each cell (ELNO).
//
// Values are stored densely, entity-major: value(entity, component). A component may be absent
// on some entities (LAGS_C exists only on slave contact nodes, DZ only in 3D): the optional
// `defined` mask says which (entity, component) pairs carry a value; without a mask every pair
// does. Per-point fields keep an offsets array: cell c owns points [offset(c), offset(c + 1)).
// Shared contract (written first by the lead): extend it, do not replace it.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace stella {

enum class FieldSupport { Node, Cell, GaussPoint, CellNode };

class Field {
public:
  // A nodal field of `nodeCount` nodes, all values 0, every component defined.
  static Field nodal(std::string quantity, std::vector<std::string> components, std::size_t nodeCount);
  // One value per cell and component.
  static Field perCell(std::string quantity, std::vector<std::string> components, std::size_t cellCount);
  // `pointsPerCell[c]` values per component in cell c (0 for cells outside the field's model).
  static Field perPoint(FieldSupport support, std::string quantity, std::vector<std::string> components,
                        const std::vector<int>& pointsPerCell);

  FieldSupport support() const { return support_; }
  const std::string& quantity() const { return quantity_; }
  const std::vector<std::string>& components() const { return components_; }
  std::optional<std::size_t> componentIndex(const std::string& name) const;
  std::size_t componentCount() const { return components_.size(); }

  // Nodes, cells or points (for per-point fields: the total number of points).
  std::size_t entityCount() const { return entities_; }
  // Per-point fields: the cell count, the number of points of a cell, its first point.
  std::size_t cellCount() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  int pointCount(std::size_t cell) const;
  std::size_t firstPoint(std::size_t cell) const { return offsets_[cell]; }

  double value(std::size_t entity, std::size_t component) const {
    return values_[entity * components_.size() + component];
  }
  double& value(std::size_t entity, std::size_t component) {
    return values_[entity * components_.size() + component];
  }
  // All components of one entity.
  std::span<const double> entity(std::size_t e) const;
  std::span<double> entity(std::size_t e);
  const std::vector<double>& values() const { return values_; }
  std::vector<double>& values() { return values_; }

  // Absent components: after markPartial(), every pair is undefined until setDefined().
  void markPartial();
  bool partial() const { return !defined_.empty(); }
  bool defined(std::size_t entity, std::size_t component) const;
  void setDefined(std::size_t entity, std::size_t component, bool on = true);

private:
  FieldSupport support_ = FieldSupport::Node;
  std::string quantity_;
  std::vector<std::string> components_;
  std::size_t entities_ = 0;
  std::vector<std::size_t> offsets_; // per-point fields only
  std::vector<double> values_;
  std::vector<std::uint8_t> defined_; // empty: all defined
};

} // namespace stella
