#pragma once
// The selections behind DEFI_GROUP (CREA_GROUP_MA, CREA_GROUP_NO), as library functions on a
// Mesh. All lists are sorted and unique unless said otherwise.

#include "solver/mesh/Mesh.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace stella {

// Set operations on sorted lists: union of all, intersection of all, first minus the others.
std::vector<std::int32_t> unionOf(const std::vector<std::vector<std::int32_t>>& lists);
std::vector<std::int32_t> intersectionOf(const std::vector<std::vector<std::int32_t>>& lists);
std::vector<std::int32_t> differenceOf(const std::vector<std::vector<std::int32_t>>& lists);

std::vector<CellId> allCells(const Mesh& mesh);
// TYPE_MAILLE: "TOUT", "0D", "1D", "2D", "3D" or a cell type name (SEG2, QUAD4...).
std::vector<CellId> filterCellType(const Mesh& mesh, const std::vector<CellId>& cells,
                                   const std::string& typeMaille);

// How many nodes of a cell must satisfy a condition (CRIT_NOEUD, TYPE_APPUI).
enum class NodeCriterion { AtLeastOne, All, Majority, Vertices };
std::vector<CellId> cellsByNodes(const Mesh& mesh, const std::vector<CellId>& cells,
                                 const std::function<bool(NodeId)>& condition, NodeCriterion criterion);

// FACE_NORMALE: faces (and edges of 2D meshes) whose normal makes an angle of at most
// `angleDegrees` with `direction` (or with -direction too when !checkSign).
std::vector<CellId> cellsFacing(const Mesh& mesh, const Point3& direction, double angleDegrees,
                                bool checkSign);
// ANGL_NAUT (alpha, beta) in degrees -> unit vector (cos a cos b, sin a cos b, -sin b).
Point3 nauticalDirection(const std::vector<double>& angles);

// CRIT_NOEUD of CREA_GROUP_NO/GROUP_MA: TOUS, SOMMET (vertices), MILIEU (mid-edge), CENTRE
// (face and cell centres).
std::vector<NodeId> nodesOfCells(const Mesh& mesh, const std::vector<CellId>& cells,
                                 const std::string& criterion);
std::vector<NodeId> nodesWhere(const Mesh& mesh, const std::function<bool(const Point3&)>& condition);

// Distances used by SPHERE/CYLINDRE/BANDE, ENV_SPHERE/ENV_CYLINDRE/PLAN.
double distanceToAxis(const Point3& x, const Point3& point, const Point3& direction);
double distanceToPlane(const Point3& x, const Point3& point, const Point3& normal);

// NOEUD_ORDO: the nodes of a chain of segment cells, in order along the chain, from `origin`
// (or from a free end; for a closed chain from its first node). Throws UserError DEFI_GROUP_5
// when the cells do not form one simple chain. The order is kept (not sorted).
std::vector<NodeId> orderedChainNodes(const Mesh& mesh, const std::vector<CellId>& segments,
                                      std::optional<NodeId> origin, std::optional<NodeId> end);
// SEGM_DROI_ORDO: the nodes lying on the segment [a, b] within `precision` (relative to its
// length when `relative`), ordered by abscissa from a.
std::vector<NodeId> nodesOnSegment(const Mesh& mesh, const std::vector<NodeId>& nodes, NodeId a, NodeId b,
                                   double precision, bool relative);

} // namespace stella
