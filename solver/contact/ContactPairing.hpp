#pragma once
// Pairing (appariement) of a contact zone: each slave node is associated with a point of the
// master surface, giving the contact link the discrete algorithms constrain.
//   MAIT_ESCL  orthogonal projection of the slave node on the master cells (SEG2/SEG3 in 2D and
//              axisymmetric models, TRIA3/TRIA6/QUAD4/QUAD8/QUAD9 in 3D): Newton (Gauss-Newton)
//              on the parametric coordinates; a projection outside its cell by more than
//              TOLE_PROJ_EXT (parametric distance) is refused, a smaller one is brought back onto
//              the cell. The node pairs with the nearest admissible projection over ALL master
//              cells (ties: CellProjection.hpp selectCandidate), found exactly with the R-tree of
//              MasterCellIndex.hpp: balls around the node grow until one holds an admissible
//              projection at distance d, then every cell whose box is within d is tried.
//   NODAL      the nearest master node, along the slave normal (ties: the smallest node id).
// DIST_APPA (> 0) refuses pairs farther apart. Normals: NORMALE MAIT (master outward normal),
// ESCL (opposite of the slave outward normal), MAIT_ESCL (their mean); VECT_MAIT/VECT_ESCL FIXE
// (given vector) or VECT_Y (given vector made orthogonal to the cell); LISSAGE: nodal normals
// averaged over the cells of the surface and interpolated with the shape functions.
// The gap JEU = (x_slave - x_projection) . n is positive when open; n is the master's outward
// normal (pointing towards the slave).

#include "solver/contact/ContactDefinition.hpp"

#include <functional>
#include <memory>
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
  int dimension = 3;       // of the mesh (2: SEG master cells)
  bool smoothing = false;  // LISSAGE
  int threads = 1;         // slave nodes paired in this many chunks at once
  bool exhaustive = false; // every master cell a candidate, no index (the brute-force reference)
};

class MasterSurface;

// The pairing of one zone kept across the geometric loop: the surfaces' topology is built once;
// each pair() reads the current positions, rebuilds the master cells' index and pairs every
// slave node, starting after the first call from its previous master cell and that cell's
// neighbours (the cells sharing a node with it): when one of them holds an admissible
// projection at distance d, only the cells whose boxes lie within d are tried besides (one box
// query, usually giving back the same few cells); otherwise the node is searched as the first
// time. The result equals the pairing from scratch (tested). The links are rewritten in place:
// after the first call nothing is allocated per node (master cells of one type).
class ZonePairing {
public:
  ZonePairing(const Mesh& mesh, int zoneIndex, const ContactZone& zone, const PairingOptions& options);
  ~ZonePairing();
  ZonePairing(ZonePairing&&) noexcept;
  ZonePairing& operator=(ZonePairing&&) noexcept;

  const std::vector<ContactLink>& pair(const NodePosition& position);
  const std::vector<ContactLink>& links() const { return links_; }
  // Slave nodes of the last pairing not held by their previous cell or its neighbours (searched
  // in the R-tree by growing balls; every node the first time).
  long searchedNodes() const { return searched_; }

private:
  struct Scratch;
  void pairRange(const NodePosition& position, std::size_t begin, std::size_t end, Scratch& scratch);
  void pairNode(const NodePosition& position, std::size_t i, Scratch& scratch);
  int findCell(const Point3& x, int previous, Scratch& scratch) const;
  NodeId findNode(const Point3& x, Scratch& scratch) const;
  void writeLink(std::size_t i, int best, const Scratch& scratch, const Point3& x, const Point3& slaveNormal);

  const Mesh* mesh_ = nullptr;
  int zoneIndex_ = 0;
  ContactZone zone_;
  PairingOptions options_;
  int dim_ = 2;
  std::vector<NodeId> slaves_;
  std::unique_ptr<MasterSurface> master_;
  std::unique_ptr<MasterSurface> slave_; // nodal normals of the slave surface, when needed
  std::vector<int> slaveLocal_;          // local number of each slave node on slave_
  std::vector<ContactLink> links_;
  std::vector<int> previous_; // master cell position of each slave node's last pairing (-1)
  std::vector<Scratch> scratch_;
  double tieTolerance_ = 0.0;
  long searched_ = 0;
  bool slaveNormalNeeded_ = false;
  bool first_ = true;
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
