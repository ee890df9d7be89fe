// Mortar pairing in 2D (see MortarSegmentPairing.hpp).

#include "solver/contact/mortar/MortarSegmentPairing.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/CellTopology.hpp"

namespace stella::mortar {

namespace {

std::vector<contact::Box3> boxes(std::span<const Segment> segments, const SearchMargin& margin) {
  std::vector<contact::Box3> out;
  out.reserve(segments.size());
  std::vector<Point3> p;
  for (const auto& s : segments) {
    STELLA_ASSERT((s.type == CellType::SEG2 || s.type == CellType::SEG3) &&
                      static_cast<int>(s.nodes.size()) == nodeCount(s.type),
                  "mortar segment");
    p.clear();
    for (const auto& x : s.nodes) {
      p.push_back({x[0], x[1], 0.0});
    }
    out.push_back(slaveBox(s.type, p.data(), static_cast<int>(p.size()), margin));
  }
  return out;
}

} // namespace

SegmentPairing pairSegments(std::span<const Segment> slaves, std::span<const Segment> masters,
                            const SegmentPairingOptions& options) {
  const Candidates candidates =
      findCandidates(boxes(slaves, options.margin), boxes(masters, {0.0, 0.0}), options.exhaustive);
  SegmentPairing out;
  for (std::size_t s = 0; s < slaves.size(); ++s) {
    const auto list = candidates.of(s);
    out.candidatePairs += list.size();
    if (!list.empty()) {
      for (const auto& o : intersectSegments(slaves[s], masters, list, options.segment)) {
        out.overlaps.push_back({o.master, o.xiMin, o.xiMax, o.length, out.points.size(), o.points.size()});
        out.points.insert(out.points.end(), o.points.begin(), o.points.end());
      }
    }
    out.offsets.push_back(out.overlaps.size());
  }
  return out;
}

} // namespace stella::mortar
