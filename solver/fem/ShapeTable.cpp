// Tabulation of shape functions at the RIGI Gauss points, cached per cell type and role.

#include "solver/fem/ShapeTable.hpp"

#include <array>
#include <memory>
#include <mutex>

namespace stella::fem {

const ShapeTable& shapeTable(CellType type, IntegrationRole role) {
  static std::array<std::array<std::unique_ptr<ShapeTable>, integrationRoleCount>, cellTypeCount> cache;
  static std::array<std::array<std::once_flag, integrationRoleCount>, cellTypeCount> once;
  const auto i = static_cast<std::size_t>(type);
  const auto j = static_cast<std::size_t>(role);
  std::call_once(once[i][j], [&] {
    const ReferenceElement& e = referenceElement(type);
    auto t = std::make_unique<ShapeTable>();
    t->type = type;
    t->nodeCount = e.nodeCount();
    t->dimension = e.dimension();
    t->rule = &rigiRule(type, role);
    for (const auto& p : t->rule->points) {
      t->values.push_back(e.values(p));
      t->gradients.push_back(e.gradients(p));
    }
    cache[i][j] = std::move(t);
  });
  return *cache[i][j];
}

} // namespace stella::fem
