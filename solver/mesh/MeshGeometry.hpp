#pragma once
// Geometric quantities of cells from their vertices (straight-sided approximation): centroid,
// length/area/signed volume, normal of faces and of edges of 2D meshes, and the jacobian
// determinant at each corner of a cell (a volume cell with a negative one is inverted; a 2D
// face is inverted, folded, when they change sign: see isInverted).

#include "solver/mesh/Mesh.hpp"

#include <cmath>
#include <vector>

namespace stella {

inline Point3 operator-(const Point3& a, const Point3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Point3 operator+(const Point3& a, const Point3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Point3 operator*(double s, const Point3& a) {
  return {s * a[0], s * a[1], s * a[2]};
}
inline double dot(const Point3& a, const Point3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Point3& a) {
  return std::sqrt(dot(a, a));
}

// Mean of the vertices.
Point3 cellCentroid(const Mesh& mesh, CellId c);
// Length of a segment, area of a face, signed volume of a volume cell (positive when the cell
// follows code_aster's orientation), 0 for a point.
double cellMeasure(const Mesh& mesh, CellId c);
// Area vector of a face (Newell's formula: normal times area, following the node order); for a
// segment, the in-plane normal (ty, -tx, 0) times the length (outward for a counter-clockwise
// 2D cell); zero for points and volumes.
Point3 cellNormal(const Mesh& mesh, CellId c);
// Jacobian determinant (triple product of the three edges) at each vertex of a volume cell that
// has exactly three edges (every vertex but a pyramid's apex), in reference orientation; for a
// face of a 2D mesh, the z-component of the cross product of the two edges at each vertex.
std::vector<double> cornerJacobians(const Mesh& mesh, CellId c);
// An inverted cell: a volume cell with a negative corner jacobian; a face (2D mesh) whose corner
// jacobians do not all have one sign (folded). A face turning clockwise is not inverted: code_aster
// (and stella) accept 2D cells numbered either way.
bool isInverted(const Mesh& mesh, CellId c);
// +1 when the cell follows code_aster's orientation (a volume with a positive volume, a face of a
// 2D mesh turning counter-clockwise in the xy plane), -1 otherwise.
int cellWinding(const Mesh& mesh, CellId c);
// Longest over shortest edge (>= 1; infinity for a cell with a zero-length edge).
double aspectRatio(const Mesh& mesh, CellId c);

} // namespace stella
