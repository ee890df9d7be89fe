#pragma once
// Mortar geometry in 2D (pure geometry, no solver): the part of a slave segment (SEG2, SEG3)
// that a master segment covers, as an interval of the slave's parametric coordinate xi in
// [-1, 1], with integration points carrying slave and master parametric coordinates.
//
// A master segment covers the slave where the normals of the slave (the in-plane normal of the
// slave curve at each point) meet it: the ends of the interval are the slave points whose normal
// line passes through a master end (found by Newton on the slave curve, exact for a SEG2), and
// each integration point is sent to the master along the slave normal at that point (Newton on
// the master curve). The candidates come from a bounding-box query done by the caller.
//
// Tolerances: an interval shorter than `minLength` (relative to the slave's parametric length 2,
// default 1e-12) is dropped, so a master touching the slave at one point (a shared node) gives
// nothing; a master segment whose tangent is perpendicular to the slave (grazing, |cos| below
// `grazingCosine`, default 1e-8) gives nothing; master ends projecting within `minLength` of a
// slave end snap to it, so masters sharing nodes tile [-1, 1] exactly.

#include "solver/mesh/CellType.hpp"

#include <array>
#include <span>
#include <vector>

namespace stella::mortar {

using Point2 = std::array<double, 2>;

struct Segment {
  CellType type = CellType::SEG2; // SEG2 or SEG3 (nodes: ends, then middle)
  std::vector<Point2> nodes;
};

struct SegmentPoint {
  double slaveXi = 0;  // in [-1, 1]
  double masterXi = 0; // in [-1, 1] when the master covers the point
  double weight = 0;   // Gauss weight times the slave length element |dx/dxi|
};

struct SegmentOverlap {
  int master = -1;             // index into the master list
  double xiMin = 0, xiMax = 0; // the slave interval
  double length = 0;           // sum of the weights (length of the slave part)
  std::vector<SegmentPoint> points;
};

struct SegmentOptions {
  int gaussPoints = 3; // per interval (Gauss-Legendre, 1..4)
  double minLength = 1e-12;
  double grazingCosine = 1e-8;
};

// Position and tangent dx/dxi of a segment at xi.
Point2 segmentPoint(const Segment& s, double xi);
Point2 segmentTangent(const Segment& s, double xi);

// The overlaps of `slave` with the `candidates` among `masters`, in the candidates' order.
std::vector<SegmentOverlap> intersectSegments(const Segment& slave, std::span<const Segment> masters,
                                              std::span<const int> candidates,
                                              const SegmentOptions& options = {});

} // namespace stella::mortar
