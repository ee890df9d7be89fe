#pragma once
// Mortar geometry in 3D (pure geometry, no solver): the part of a slave face that a master face
// covers, by clipping polygons in the slave face's plane (Puso and Laursen's segment-based
// integration, as in code_aster's LAC pairing):
//   1. the slave plane: through the centroid of the slave vertices, normal n = the slave's Newell
//      normal (exact for a flat face; the average plane of a warped quadrangle);
//   2. the slave polygon: its vertices projected on the plane (the linear hull of TRIA6, QUAD8,
//      QUAD9: their vertices); each candidate master polygon: its vertices projected along n;
//   3. the master polygon clipped by the slave one (Sutherland-Hodgman; the slave polygon is
//      convex), both turned counter-clockwise around n;
//   4. the intersection polygon cut in triangles from its centroid, with Gauss points (a
//      triangle rule of degree 1, 2, 3 or 5), each sent to the slave and the master linear hulls
//      along n to give its parametric coordinates (code_aster's reference cells: TRIA3 on
//      (0,0),(1,0),(0,1), QUAD4 on [-1,1]^2).
// Weights are areas in the slave plane, so the weights of all masters covering a flat slave
// face add up to its area.
//
// Tolerances (`relativeTolerance` eps, default 1e-12, times the slave's diameter h): a vertex
// within eps*h of a clipping line counts as on it (no intersection point is made next to it,
// so shared edges and vertices give no slivers and no duplicate points); consecutive vertices
// closer than eps*h merge; an intersection of area below eps*h^2 (a master touching the slave
// along an edge or at a vertex) is dropped. A master face whose normal makes with n a cosine
// below `grazingCosine` in absolute value (seen edge-on, default 1e-8) is skipped; a nearly
// parallel one (cosine near 1) is an ordinary case. Masters facing either way are accepted.

#include "solver/mesh/CellType.hpp"
#include "solver/mesh/Mesh.hpp"

#include <array>
#include <span>
#include <vector>

namespace stella::mortar {

struct Face {
  CellType type = CellType::TRIA3; // TRIA3, TRIA6, TRIA7, QUAD4, QUAD8, QUAD9
  std::vector<Point3> nodes;       // code_aster order (vertices first)
};

struct PolygonPoint {
  std::array<double, 2> slave{};  // parametric coordinates on the slave's linear hull
  std::array<double, 2> master{}; // on the master's linear hull
  Point3 x{};                     // the point in the slave plane
  double weight = 0;              // area weight
};

struct PolygonOverlap {
  int master = -1;
  double area = 0;
  std::vector<Point3> polygon; // counter-clockwise around the slave normal, in the slave plane
  std::vector<PolygonPoint> points;
};

struct PolygonOptions {
  int degree = 2; // of the triangle rule: 1 (1 point), 2 (3), 3 (4), 5 (7)
  double relativeTolerance = 1e-12;
  double grazingCosine = 1e-8;
};

// The overlaps of `slave` with the `candidates` among `masters`, in the candidates' order.
std::vector<PolygonOverlap> intersectFaces(const Face& slave, std::span<const Face> masters,
                                           std::span<const int> candidates,
                                           const PolygonOptions& options = {});

// Convex polygon clipping in 2D (counter-clockwise input; for tests and the kernel): the part of
// `subject` inside `clip`, vertices within `eps` of a clipping line counting as on it.
using Point2d = std::array<double, 2>;
std::vector<Point2d> clipConvex(const std::vector<Point2d>& subject, const std::vector<Point2d>& clip,
                                double eps);
double polygonArea(const std::vector<Point2d>& p); // signed (counter-clockwise positive)

} // namespace stella::mortar
