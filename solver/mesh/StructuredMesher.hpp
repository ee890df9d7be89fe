#pragma once
// Structured meshes of rectangles and boxes for tests and test cases (tools/mesh/stella-mesh):
//   rectangle [x0, x0+lx] x [y0, y0+ly] in QUAD4, QUAD8, QUAD9, TRIA3 or TRIA6 (each quadrangle
//   split along its (0,0)-(1,1) diagonal); box in HEXA8, HEXA20, HEXA27, TETRA4, TETRA10 (six
//   tetrahedra per hexahedron around its main diagonal), PENTA6, PENTA15 or PENTA18 (two prisms
//   per hexahedron).
// Groups: the cells (SURFACE in 2D, VOLUME in 3D); boundary cells (SEG in 2D, QUAD/TRIA in 3D)
// oriented outward in XMIN, XMAX, YMIN, YMAX (and ZMIN, ZMAX); node groups of the same names;
// node group ORIGIN (the corner at the origin). Nodes are numbered x fastest, then y, then z.

#include "solver/mesh/Mesh.hpp"

namespace stella {

struct StructuredSpec {
  CellType type = CellType::QUAD4;
  std::array<int, 3> divisions{1, 1, 1}; // nz ignored in 2D
  std::array<double, 3> lengths{1.0, 1.0, 1.0};
  std::array<double, 3> origin{0.0, 0.0, 0.0};
};

// Throws UserError MESHGEN_1 for a cell type it cannot build or non-positive sizes.
Mesh buildStructuredMesh(const StructuredSpec& spec);

} // namespace stella
