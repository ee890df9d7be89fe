#pragma once
// Gauss integration rules on the reference elements, named as code_aster names its families
// (FPG1, FPG3, FPG4, FPG5, FPG6, FPG8, FPG9, FPG21, FPG27...), and the rule code_aster uses for
// full integration (family RIGI) of each cell type, as a volume of its modelling or as a skin.
// The point counts are listed in doc/fem.md.

#include "solver/mesh/CellType.hpp"

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace stella::fem {

struct QuadratureRule {
  std::string name;                    // code_aster family name, e.g. "FPG27"
  int degree = 0;                      // total polynomial degree integrated exactly
  std::vector<Eigen::Vector3d> points; // reference coordinates
  std::vector<double> weights;
  int size() const { return static_cast<int>(weights.size()); }
};

// How a cell is integrated: as the volume of the modelling (a TRIA3 of a D_PLAN model, a HEXA8
// of a 3D model), as an axisymmetric volume (code_aster integrates AXIS TRIA6 with FPG6 instead
// of FPG3), or as a skin carrying loads/contact (a SEG2 edge in 2D, a TRIA3 face in 3D).
enum class IntegrationRole { Volume, Skin, AxisymmetricVolume };
inline constexpr int integrationRoleCount = 3;

// The full-integration (RIGI) rule of a cell type in a role; built once, thread-safe.
const QuadratureRule& rigiRule(CellType type, IntegrationRole role);

// A named rule of a cell type's reference shape (for tests and other families), e.g.
// namedRule(CellType::TETRA10, "FPG4").
QuadratureRule namedRule(CellType type, const std::string& family);

} // namespace stella::fem
