#pragma once
// Pairing (appariement) of a contact zone: each slave node is associated with a point of the
// master surface, giving the contact link the discrete algorithms constrain.
//   MAIT_ESCL  orthogonal projection of the slave node on the master cells (SEG2/SEG3 in 2D and
//              axisymmetric models, TRIA3/TRIA6/QUAD4/QUAD8/QUAD9 in 3D): Newton (Gauss-Newton)
//              on the parametric coordinates, on the cells around the nearest master nodes found
//              with a kd-tree; a projection outside its cell by more than TOLE_PROJ_EXT
//              (parametric distance) is refused, a smaller one is brought back onto the cell.
//   NODAL      the nearest master node, along the slave normal.
// DIST_APPA (> 0) refuses pairs farther apart. Normals: NORMALE MAIT (master outward normal),
// ESCL (opposite of the slave outward normal), MAIT_ESCL (their mean); VECT_MAIT/VECT_ESCL FIXE
// (given vector) or VECT_Y (given vector made orthogonal to the cell); LISSAGE: nodal normals
// averaged over the cells of the surface and interpolated with the shape functions.
// The gap JEU = (x_slave - x_projection) . n is positive when open; n is the master's outward
// normal (pointing towards the slave).

#include "solver/contact/ContactDefinition.hpp"

#include <functional>
#include <vector>

namespace stella::contact {

// Current position of a node (initial coordinates plus displacement).
using NodePosition = std::function<Point3(NodeId)>;

struct ContactLink {
  int zone = 0;
  NodeId slave = -1;
  bool paired = false;            // false: no admissible projection (CONT = -1)
  CellId masterCell = -1;         // -1 for NODAL pairing
  std::array<double, 2> xi{0, 0}; // parametric coordinates on the master cell
  std::vector<NodeId> masterNodes;
  std::vector<double> weights; // shape-function values at xi on masterNodes
  Point3 normal{0, 0, 0};      // unit, master outward (towards the slave)
  Point3 tangent1{0, 0, 0};
  Point3 tangent2{0, 0, 0};   // zero in 2D
  Point3 projection{0, 0, 0}; // the paired point of the master surface
  double gap = 0.0;           // JEU, positive when open
};

struct PairingOptions {
  int dimension = 3;      // of the mesh (2: SEG master cells)
  bool smoothing = false; // LISSAGE
};

// Pairs every slave node of the zone (minus SANS_GROUP_NO / SANS_GROUP_MA). Links keep the
// order of zoneSlaveNodes. Throws UserError for options not implemented yet
// (TYPE_PROJECTION='FIXE').
std::vector<ContactLink> pairZone(const Mesh& mesh, const NodePosition& position, int zoneIndex,
                                  const ContactZone& zone, const PairingOptions& options);

// Every zone of a definition, in zone order.
std::vector<ContactLink> pairAll(const ContactDefinition& definition, const NodePosition& position);

// Positions from the mesh coordinates plus an optional displacement (3 values per node; empty:
// the initial configuration).
NodePosition meshPositions(const Mesh& mesh, const std::vector<double>* displacement);

// Projection of a point on one master cell: parametric coordinates minimising the distance
// (Gauss-Newton, at most 50 iterations). Returns the unclamped coordinates.
std::array<double, 2> projectOnCell(const Mesh& mesh, const NodePosition& position, CellId cell,
                                    const Point3& x);

} // namespace stella::contact
