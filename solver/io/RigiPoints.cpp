#include "RigiPoints.hpp"

#include "solver/fem/Quadrature.hpp"

#include <exception>

namespace stella {

std::vector<Point3> rigiGaussPoints(CellType type, int count) {
  for (const auto role : {fem::IntegrationRole::Volume, fem::IntegrationRole::Skin}) {
    try {
      const auto& rule = fem::rigiRule(type, role);
      if (rule.size() == count) {
        std::vector<Point3> p;
        for (const auto& x : rule.points) {
          p.push_back({x[0], x[1], x[2]});
        }
        return p;
      }
    } catch (const std::exception&) {
      // No rule of this role for this type: try the next one.
    }
  }
  return {};
}

} // namespace stella
