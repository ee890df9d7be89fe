#pragma once
// The Gauss points of code_aster's RIGI family for a cell type and a point count (volume rule,
// or skin rule for boundary cells): what IMPR_RESU and the MED file of a failed run write as
// the localisation of Gauss-point fields. Empty when no rule has `count` points.

#include "solver/io/ResultWriters.hpp"

#include <vector>

namespace stella {

std::vector<Point3> rigiGaussPoints(CellType type, int count);

} // namespace stella
