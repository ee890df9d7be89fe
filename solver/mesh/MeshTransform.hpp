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
// the mesh's top dimension when empty). Returns the number of cells reversed. Throws UserError
// ORIE_PEAU_1 for a skin cell bounding no volume cell, ORIE_PEAU_2 for one bounding two (an
// internal skin: give the side's cells in `volumes`).
int orientSkin(Mesh& mesh, const std::vector<CellId>& skin, const std::vector<CellId>& volumes);

} // namespace stella
