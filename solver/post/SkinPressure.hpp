#pragma once
// PRES_NOEU (CALC_PRESSION): the normal pressure p = -n.sigma.n on skin cells, from a nodal
// stress field (SIXX, SIYY, SIZZ, SIXY [, SIXZ, SIYZ]).
//   - n is the unit normal of the skin cell at each of its nodes, from the derivatives of the
//     cell's shape functions at the node (exact on curved quadratic edges and faces), on the
//     coordinates `x` given (initial, or deformed = initial + DEPL); its sign does not matter;
//   - at a node shared by several skin cells (a corner of the skin), p is the mean of the cells'
//     values;
//   - the field has the component PRES on the skin nodes only (the others carry no value).
// A compressive normal stress gives a positive pressure, as a pressure load PRES_REP.

#include "solver/database/Field.hpp"
#include "solver/mesh/Mesh.hpp"

#include <vector>

namespace stella {

// `x`: the coordinates of every node; `skin`: cells of dimension mesh.dimension() - 1.
Field skinPressure(const Mesh& mesh, const std::vector<Point3>& x, const Field& nodalStress,
                   const std::vector<CellId>& skin);

} // namespace stella
