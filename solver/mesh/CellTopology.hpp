#pragma once
// Reference topology of every CellType in code_aster's node ordering: vertices, edges (with their
// mid-edge node for quadratic types), faces of volume cells (outward-oriented, with mid-edge and
// face-centre nodes when the type has them), the linear and quadratic counterparts of a type, and
// the reference coordinates of the nodes.
//
// code_aster's orderings (0-based here): vertices first; then one node per edge in the order
//   TRIA  (0,1) (1,2) (2,0)                    QUAD  (0,1) (1,2) (2,3) (3,0), then centre 8
//   TETRA (0,1) (1,2) (2,0) (0,3) (1,3) (2,3)
//   PENTA (0,1) (1,2) (2,0) (0,3) (1,4) (2,5) (3,4) (4,5) (5,3), then centres of the quadrangles
//         (0,1,4,3) (1,2,5,4) (2,0,3,5) for PENTA18
//   PYRAM (0,1) (1,2) (2,3) (3,0) (0,4) (1,4) (2,4) (3,4)
//   HEXA  (0,1) (1,2) (2,3) (3,0) (0,4) (1,5) (2,6) (3,7) (4,5) (5,6) (6,7) (7,4), then centres
//         of the faces (0,1,2,3) (0,1,5,4) (1,2,6,5) (2,3,7,6) (3,0,4,7) (4,5,6,7), then the
//         cell centre for HEXA27
// Volume cells are positively oriented: for TETRA4, (p1-p0)x(p2-p0).(p3-p0) > 0; for HEXA8 the
// face (0,1,2,3) turns counter-clockwise seen from the face (4,5,6,7).

#include "solver/mesh/CellType.hpp"

#include <array>
#include <span>
#include <vector>

namespace stella {

// The shape family of a cell type (its linear geometry).
enum class CellShape : std::uint8_t {
  Point,
  Segment,
  Triangle,
  Quadrangle,
  Tetrahedron,
  Pentahedron,
  Pyramid,
  Hexahedron
};

CellShape shapeOf(CellType t);
// Number of vertex (corner) nodes: 1, 2, 3, 4, 4, 6, 5, 8.
int vertexCount(CellType t);
// The linear type of the same shape (TRIA6 -> TRIA3).
CellType linearType(CellType t);
// The quadratic type without centre nodes (TRIA3 -> TRIA6, HEXA8 -> HEXA20, POI1 -> POI1).
CellType quadraticType(CellType t);

// One edge: its two vertices and, for types with mid-edge nodes, the mid node (-1 otherwise).
struct CellEdge {
  int a = 0;
  int b = 0;
  int mid = -1;
};

// Edges in code_aster's order (for SEG types the segment itself).
std::vector<CellEdge> cellEdges(CellType t);

// One face (boundary entity of dimension dim-1): its cell type and local node indices, oriented
// so that the normal points out of the cell (for 2D cells the "faces" are the edges, ordered so
// that the outward in-plane normal is (ty, -tx) for a counter-clockwise cell).
struct CellFace {
  CellType type;
  std::vector<int> nodes;
};

std::vector<CellFace> cellFaces(CellType t);

// Coordinates of the nodes of a positively oriented unit cell of the type, in the node order
// above: SEG [-1,1], TRIA unit triangle, QUAD [-1,1]^2, TETRA unit tetrahedron, PENTA unit
// triangle x [-1,1], PYRAM base [-1,1]^2 apex (0,0,1), HEXA [-1,1]^3; quadratic nodes at the
// middle of their edge, centre nodes at the centre of their face or cell.
std::vector<std::array<double, 3>> referenceCoordinates(CellType t);

} // namespace stella
