#pragma once
// MODI_MAILLAGE operations as library functions: rigid motions and scaling of the nodes
// (TRANSLATION, ROTATION, ECHELLE, SYMETRIE) and skin orientation (ORIE_PEAU, ORIE_PEAU_2D/3D).

#include "solver/mesh/Mesh.hpp"

#include <vector>

namespace stella {

// The node permutation that reverses a cell's orientation: new[i] = old[perm[i]] (keeps the
// first vertex; mid-edge and centre nodes follow their edges and faces).
std::vector<int> orientationReversal(CellType t);
void reverseCell(Mesh& mesh, CellId c);

void translateMesh(Mesh& mesh, const Point3& v);
// Rotation by `degrees` about the axis through `point` with direction `axis` (right-hand rule).
void rotateMesh(Mesh& mesh, const Point3& point, const Point3& axis, double degrees);
void scaleMesh(Mesh& mesh, double factor);
// Mirror through the line (2D: point + AXE_1) or the plane (3D: point, spanned by axis1 and
// axis2); every cell of dimension >= 1 is then reversed so volumes keep a positive jacobian and
// skins keep their side.
void mirrorMesh(Mesh& mesh, const Point3& point, const Point3& axis1, const Point3* axis2);

// ORIE_PEAU: orients every cell of `skin` (faces in 3D, segments in 2D) so that its normal
// points out of the volume (surface in 2D) cell it bounds, chosen among `volumes` (every cell of
// the mesh's top dimension when empty), whatever that cell's own winding (SkinOrientation.hpp).
// A skin cell bounding no volume cell (a rigid surface) is oriented coherently with the skin
// cells of `skin` it is connected to (shared edges in 3D, shared nodes in 2D); a connected set
// of such cells touching no oriented cell is made coherent within itself and listed in
// `unanchored` (the caller warns). Throws UserError ORIE_PEAU_2 for a cell bounding two volume
// cells (an internal skin: give the side's cells in `volumes`), ORIE_PEAU_3 for a cell that is
// not a skin cell.
struct SkinOrientationSummary {
  int reversed = 0;               // cells whose node order was reversed
  std::vector<CellId> unanchored; // cells oriented only coherently with each other
};
SkinOrientationSummary orientSkin(Mesh& mesh, const std::vector<CellId>& skin,
                                  const std::vector<CellId>& volumes);

} // namespace stella
