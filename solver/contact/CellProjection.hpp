#pragma once
// The projection kernel of the pairing, on one master cell given by its type and node positions
// (a fixed array: nothing allocated): geometry at parametric coordinates, orthogonal projection
// of a point (Gauss-Newton), parametric distance outside the reference cell, and the candidate
// a cell offers to a slave node.

#include "solver/contact/SurfaceShape.hpp"
#include "solver/mesh/Mesh.hpp"

#include <array>
#include <limits>

namespace stella::contact {

struct CellNodes {
  CellType type = CellType::SEG2;
  int count = 0;
  std::array<Point3, maxSurfaceNodes> x{};
};

struct CellPoint {
  Point3 x{0, 0, 0};
  Point3 d1{0, 0, 0}; // dx/dxi
  Point3 d2{0, 0, 0}; // dx/deta (3D)
  SurfaceShapeValues shape;
};

// Position, derivatives and shape values at xi.
void evaluateCell(const CellNodes& cell, const std::array<double, 2>& xi, CellPoint& out);

// Parametric coordinates minimising |x(xi) - p| (Gauss-Newton from the cell centre, at most 50
// iterations, iterates kept in [-10, 10]); unclamped.
std::array<double, 2> projectPoint(const CellNodes& cell, int dim, const Point3& p);

// Parametric distance outside the reference cell (0 inside) and the nearest inside point
// (segments, quadrangles: clamped per coordinate; triangles: onto the nearest side).
double outsideDistance(CellType type, int dim, const std::array<double, 2>& xi,
                       std::array<double, 2>& clamped);

// What a master cell offers a slave node: the projection brought back onto the cell, its
// distance to the node and how far outside the cell it fell.
struct Candidate {
  int cell = -1; // position of the cell in the zone's master cells
  std::array<double, 2> xi{0, 0};
  double distance = std::numeric_limits<double>::max();
  double outside = 0.0;
  bool admissible = false; // outside <= TOLE_PROJ_EXT
};

// extensionTolerance < 0: every projection admissible (TOLE_PROJ_EXT negative).
Candidate projectionCandidate(const CellNodes& cell, int position, int dim, const Point3& p,
                              double extensionTolerance);

// The tie rule of the pairing (brute force uses it too): among the admissible candidates, those
// within `tieTolerance` of the smallest distance tie; of them the smallest `outside` wins (a
// cell holding the projection before one reaching it by extension), then the smallest position
// (the order of the master cells in the zone). Returns the index in [first, last) or -1.
int selectCandidate(const Candidate* first, const Candidate* last, double tieTolerance);

} // namespace stella::contact
