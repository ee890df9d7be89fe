#pragma once
// Shape functions of the contact surface cells (SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, QUAD9) in
// closed form, in code_aster's node orderings and reference coordinates (the same functions as
// fem::referenceElement, which the tests check), written into caller-owned fixed arrays: the
// pairing evaluates them millions of times and must not allocate.

#include "solver/mesh/CellType.hpp"

#include <array>

namespace stella::contact {

constexpr int maxSurfaceNodes = 9;

struct SurfaceShapeValues {
  int count = 0;                              // number of nodes
  std::array<double, maxSurfaceNodes> n{};    // N_i
  std::array<double, maxSurfaceNodes> dxi{};  // dN_i/dxi
  std::array<double, maxSurfaceNodes> deta{}; // dN_i/deta (0 for segments)
};

// True for the cell types above.
bool isSurfaceShape(CellType type);

// Values and derivatives at (xi, eta) (eta unused for segments). Precondition: isSurfaceShape.
void surfaceShape(CellType type, double xi, double eta, SurfaceShapeValues& out);

// A bound of sum_i |N_i| over the reference cell (the Lebesgue constant of the interpolation):
// every point of the cell lies in the box of its nodes scaled by this factor about its centre.
double lebesgueBound(CellType type);

} // namespace stella::contact
