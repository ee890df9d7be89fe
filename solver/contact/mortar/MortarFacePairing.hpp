#pragma once
// Mortar pairing in 3D (APPARIEMENT='MORTAR'): for every slave face of a contact surface, the
// master faces it overlaps, with the overlap's area and integration points.
//   1. search (MortarSearch): each slave face's box, inflated by the margin, is queried in an
//      R-tree of the master faces' boxes: O(n log n) for n faces, candidates in ascending order;
//   2. clipping (MortarPolygons, intersectFaces): each candidate master projected along the slave
//      normal onto the slave plane and clipped by the slave polygon; masters touching the slave
//      only along an edge or at a vertex, seen edge-on (grazing) or too far to be candidates
//      give no overlap; masters facing the slave or facing the same way are both accepted.
// The search is a distance cut-off: a master farther from the slave face's box than the margin
// (SearchMargin: absolute, plus 0.25 of the face's size by default) is not a candidate, however
// it projects. The default pairs across gaps up to a quarter of the slave faces' size; across
// a larger gap set `margin.absolute` to it (the formulation knows its largest gap to pair).
// `unpairedSlaves` counts the slaves left without any overlap.
// Slave and master faces: TRIA3, TRIA6, TRIA7, QUAD4, QUAD8, QUAD9 (their linear hull is
// clipped, MortarPolygons.hpp). A degenerate slave face (zero area) has no overlap and is
// counted in `degenerateSlaves`.
//
// The result is stored flat (three arrays, no allocation per overlap): at 10^6 slave faces the
// integration points dominate the memory; `keepPoints = false` and `keepPolygons = false` leave
// only (master, area) per overlap.
//
// The search (boxes in, candidates per slave out) is the same for segments in 2D
// (MortarSegmentPairing.hpp): a 2D mortar formulation can call findCandidates directly.

#include "solver/contact/ContactPairing.hpp"
#include "solver/contact/mortar/MortarPolygons.hpp"
#include "solver/contact/mortar/MortarSearch.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace stella::mortar {

struct FacePairingOptions {
  PolygonOptions polygon{}; // rule degree and clipping tolerances
  SearchMargin margin{};    // inflation of the slave boxes
  bool keepPoints = true;   // store the integration points
  bool keepPolygons = true; // store the overlap polygons
  bool exhaustive = false;  // every master a candidate of every slave (reference for tests)
  int threads = 1;          // slave faces split in contiguous chunks (same result for any count)
};

struct FaceOverlap {
  int master = -1;
  double area = 0; // in the slave plane
  std::size_t firstPoint = 0;
  std::size_t pointCount = 0;
  std::size_t firstVertex = 0;
  std::size_t vertexCount = 0;
};

struct FacePairing {
  std::vector<std::size_t> offsets{0}; // slave s: overlaps[offsets[s] .. offsets[s + 1])
  std::vector<FaceOverlap> overlaps;   // per slave, masters in ascending order
  std::vector<PolygonPoint> points;    // when keepPoints
  std::vector<Point3> vertices;        // polygons, when keepPolygons
  std::size_t candidatePairs = 0;      // pairs clipped (the search's output)
  std::size_t degenerateSlaves = 0;
  std::size_t unpairedSlaves = 0; // slaves without any overlap (degenerate ones included)

  std::size_t slaveCount() const { return offsets.size() - 1; }
  std::span<const FaceOverlap> of(std::size_t slave) const {
    return {overlaps.data() + offsets[slave], offsets[slave + 1] - offsets[slave]};
  }
  std::span<const PolygonPoint> pointsOf(const FaceOverlap& o) const {
    return {points.data() + o.firstPoint, o.pointCount};
  }
  std::span<const Point3> polygonOf(const FaceOverlap& o) const {
    return {vertices.data() + o.firstVertex, o.vertexCount};
  }
  double coveredArea(std::size_t slave) const; // sum of the slave's overlap areas
  std::size_t bytes() const;                   // memory held by the arrays
};

FacePairing pairFaces(std::span<const Face> slaves, std::span<const Face> masters,
                      const FacePairingOptions& options = {});

// The faces of mesh cells at the given positions (TYPE_JACOBIEN: the initial or the current
// configuration), in the order of `cells`. Cells that are not faces are a programming error.
std::vector<Face> meshFaces(const Mesh& mesh, std::span<const CellId> cells,
                            const contact::NodePosition& position);

} // namespace stella::mortar
