#pragma once
// The cuts of CREA_MAILLAGE/DECOUPE_LAC, one cell at a time: a volume cell (a face in 2D) is cut
// along one of its faces (edges in 2D), the slave face, so that the slave face becomes a patch
// of smaller faces (code_aster's counts of cells and nodes, MESH1_3):
//   2D  TRIA3/SEG2  -> 2 TRIA3, 2 SEG2 (the edge's middle)
//       QUAD4/SEG2  -> 4 QUAD4, 3 SEG2 (two nodes on the edge at 1/3 and 2/3, two inside)
//       TRIA6, QUAD8 with a SEG3: not cut (the SEG3 is the patch)
//   3D  cone cuts, from the centre c of the slave face to every other face of the cell (a
//       triangle gives a tetrahedron, a quadrangle a pyramid); the slave face becomes a fan of
//       triangles around c: TETRA4 -> 3 TETRA4; PENTA6 -> 3 PYRAM5 + 1 TETRA4 (triangle face) or
//       2 PYRAM5 + 2 TETRA4 (quadrangle face); PYRAM5 -> 4 TETRA4 (base) or 1 PYRAM5 + 3 TETRA4;
//       HEXA8 with DECOUPE_HEXA='PYRA' -> 5 PYRAM5; the quadratic cells (TETRA10, PENTA15,
//       PYRAM13, HEXA20) the same in quadratic cells.
//       HEXA8/HEXA20 with DECOUPE_HEXA='HEXA' -> 6 hexahedra: a small one on the middle of the
//       face, four around it, one above; the face becomes 5 quadrangles.
//       HEXA27 with a QUAD9: not cut (the QUAD9 is the patch).
// Every other face of the cell is left as it is (same nodes), so the cut mesh stays conforming
// with the cells around. New nodes are placed by the cell's own isoparametric map at points of
// its reference element (a curved quadratic cell keeps its shape); the pieces keep the cell's
// orientation (positive volumes; a clockwise 2D cell gives clockwise pieces), the face pieces the
// orientation of the slave cell.

#include "solver/mesh/Mesh.hpp"

#include <span>
#include <vector>

namespace stella {

// DECOUPE_HEXA: how hexahedra are cut.
enum class LacHexaCut { Pyramids, Hexahedra };

struct LacPiece {
  CellType type = CellType::POI1;
  std::vector<NodeId> nodes;
};

struct LacCut {
  std::vector<LacPiece> cells;     // the pieces of the cut cell
  std::vector<LacPiece> faces;     // the pieces of the slave face (its orientation)
  std::vector<NodeId> faceNodes;   // new nodes on the slave face
  std::vector<NodeId> insideNodes; // new nodes inside the cell
};

enum class LacCutKind { Cut, Kept, Unsupported };

// What DECOUPE_LAC does to a `cell` whose face of type `face` is a slave cell.
LacCutKind lacCutKind(CellType cell, CellType face);

// Cuts `cell` along its local face `face` (index in cellFaces(cell.type)), whose slave cell has
// the nodes `slaveNodes` (the same nodes as the face, in the slave cell's order). New nodes are
// added to `mesh`, which must hold the cell's nodes. Requires lacCutKind(...) == Cut.
LacCut cutCellForLac(Mesh& mesh, const LacPiece& cell, int face, std::span<const NodeId> slaveNodes,
                     LacHexaCut mode);

} // namespace stella
