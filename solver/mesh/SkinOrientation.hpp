#pragma once
// One definition of "outward" for skin cells, used by MODI_MAILLAGE/ORIE_PEAU (which makes it
// true) and DEFI_CONTACT/VERI_NORM (which checks it).
//
// A skin cell (an edge of a 2D mesh, a face of a 3D mesh) bounds a volume cell (a face of a 2D
// mesh, a volume of a 3D mesh) when its vertices are those of a face of the volume cell. Its
// normal (cellNormal: (ty, -tx) for an edge, the right-hand rule for a face) points out of that
// cell when its node order runs like the face's outward cycle of the reference cell and the
// volume cell is oriented like the reference cell, or against that cycle and the volume cell is
// reversed (a 2D cell numbered clockwise, as Salome and older meshers write them). The volume
// cell's own winding (cellWinding) thus never decides alone.

#include "solver/mesh/Mesh.hpp"

#include <vector>

namespace stella {

struct BoundedVolume {
  CellId volume = -1;
  bool outward = false; // the skin cell's normal points out of `volume`
};

// For each cell of `skin`, the cells among `volumes` (every cell of the mesh's top dimension
// when empty) it bounds, with the side its normal points to. A skin cell of a dimension other
// than the top dimension minus one bounds nothing.
std::vector<std::vector<BoundedVolume>> boundedVolumes(const Mesh& mesh, const std::vector<CellId>& skin,
                                                       const std::vector<CellId>& volumes);

} // namespace stella
