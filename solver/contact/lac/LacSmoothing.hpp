#pragma once
// LISSAGE='OUI' with LAC in 2D (LacPairing.hpp averagedNormals): the averaged normals at the nodes of
// one slave cell as functions of the nodal positions, for the consistent tangent of ALGO_RESO_GEOM=
// 'NEWTON' (LacOverlapTerms.hpp): the normal at a node is the normalised sum of the outward normals
// of the zone's slave cells there, so it depends on the cell's own nodes (seeded as in the overlap,
// 2 i + c) and on the other nodes of its neighbours (seeded 12 + 2 e + c).

#include "solver/contact/lac/LacOverlapTerms.hpp"
#include "solver/contact/lac/LacPairing.hpp"

#include <map>
#include <vector>

namespace stella::contact::lac {

// node -> the zone's slave cells holding it (indices into zone.slaves, in their order)
using SlaveAdjacency = std::map<NodeId, std::vector<std::size_t>>;
SlaveAdjacency slaveAdjacency(const Mesh& mesh, const LacZoneCells& zone);

struct SmoothedStencil {
  std::vector<NodeId> neighbours;                         // seeded at 12 + 2 e
  std::array<mortar::kernel::Vec2<LacDual>, 3> normals{}; // at the slave cell's nodes
};

// The averaged normals at the nodes of zone.slaves[k] at the positions X + u (3 per node), with their
// derivatives; more than kNeighbourNodes neighbour nodes (a slave node shared by more than two slave
// cells): the normals without derivatives.
SmoothedStencil smoothedStencil(const Mesh& mesh, const LacZoneCells& zone, const SlaveAdjacency& adjacency,
                                std::size_t k, const std::vector<double>& u);

} // namespace stella::contact::lac
