#pragma once
// Mortar pairing in 2D: for every slave segment (SEG2, SEG3) the master segments it overlaps,
// through the same search as the faces (MortarSearch: boxes in the plane z = 0, R-tree, O(n log
// n)) and the segment kernel (MortarSegments, intersectSegments). The stored result mirrors
// FacePairing (MortarFacePairing.hpp): flat arrays, per slave the overlaps in ascending master
// order, each with its slave interval, its length and its integration points.

#include "solver/contact/mortar/MortarSearch.hpp"
#include "solver/contact/mortar/MortarSegments.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace stella::mortar {

struct SegmentPairingOptions {
  SegmentOptions segment{}; // Gauss points and tolerances
  SearchMargin margin{};    // inflation of the slave boxes
  bool exhaustive = false;  // every master a candidate of every slave (reference for tests)
};

struct SegmentOverlapRecord {
  int master = -1;
  double xiMin = 0, xiMax = 0; // the slave interval
  double length = 0;
  std::size_t firstPoint = 0;
  std::size_t pointCount = 0;
};

struct SegmentPairing {
  std::vector<std::size_t> offsets{0}; // slave s: overlaps[offsets[s] .. offsets[s + 1])
  std::vector<SegmentOverlapRecord> overlaps;
  std::vector<SegmentPoint> points;
  std::size_t candidatePairs = 0;

  std::size_t slaveCount() const { return offsets.size() - 1; }
  std::span<const SegmentOverlapRecord> of(std::size_t slave) const {
    return {overlaps.data() + offsets[slave], offsets[slave + 1] - offsets[slave]};
  }
  std::span<const SegmentPoint> pointsOf(const SegmentOverlapRecord& o) const {
    return {points.data() + o.firstPoint, o.pointCount};
  }
};

SegmentPairing pairSegments(std::span<const Segment> slaves, std::span<const Segment> masters,
                            const SegmentPairingOptions& options = {});

} // namespace stella::mortar
