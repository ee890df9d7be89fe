#pragma once
// POST_RELEVE_T OPERATION='MOYENNE': moments of nodal values along a path, the nodes taken in the
// order of the GROUP_NO (or NOEUD list) as code_aster does, with the curvilinear abscissa s the
// cumulated straight distance between consecutive nodes (length L). The values are taken linear
// between consecutive nodes (the trapezoidal rule, exact for such values):
//   MOMENT_0 = (1/L) int f ds                 the mean;
//   MOMENT_1 = (6/L^2) int f (s - L/2) ds     the linearised "bending" part: the least-squares
//                                             line through f is MOMENT_0 + MOMENT_1 (2s/L - 1);
//   MINIMUM, MAXIMUM of the nodal values.
// A single node (L = 0) gives its value as MOMENT_0 and 0 as MOMENT_1.

#include "solver/mesh/Mesh.hpp"

#include <vector>

namespace stella {

struct PathMoments {
  double length = 0.0;
  double moment0 = 0.0;
  double moment1 = 0.0;
  double minimum = 0.0;
  double maximum = 0.0;
};

// `points` and `values` have the same, non-zero size.
PathMoments pathMoments(const std::vector<Point3>& points, const std::vector<double>& values);

} // namespace stella
