// Boost.Geometry R-tree of master cell boxes (header-only Boost, Debian libboost-dev).

#include "solver/contact/MasterCellIndex.hpp"

#include "solver/contact/SurfaceShape.hpp"

#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <iterator>
#include <utility>

namespace stella::contact {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

namespace {

using BgPoint = bg::model::point<double, 3, bg::cs::cartesian>;
using BgBox = bg::model::box<BgPoint>;
using Value = std::pair<BgBox, int>;

BgBox toBoost(const Box3& b) {
  return {BgPoint(b.lo[0], b.lo[1], b.lo[2]), BgPoint(b.hi[0], b.hi[1], b.hi[2])};
}

// Output iterator appending the value's position (avoids a vector of pairs per query).
struct PositionSink {
  using iterator_category = std::output_iterator_tag;
  using value_type = void;
  using difference_type = std::ptrdiff_t;
  using pointer = void;
  using reference = void;
  std::vector<int>* out;
  PositionSink& operator*() { return *this; }
  PositionSink& operator++() { return *this; }
  PositionSink operator++(int) { return *this; }
  PositionSink& operator=(const Value& v) {
    out->push_back(v.second);
    return *this;
  }
};

} // namespace

struct MasterCellIndex::Tree {
  bgi::rtree<Value, bgi::rstar<16>> rtree;
};

Box3 cellBox(CellType type, const Point3* points, int count, double margin) {
  Box3 b{points[0], points[0]};
  for (int i = 1; i < count; ++i) {
    for (std::size_t a = 0; a < 3; ++a) {
      b.lo[a] = std::min(b.lo[a], points[i][a]);
      b.hi[a] = std::max(b.hi[a], points[i][a]);
    }
  }
  const double scale = lebesgueBound(type);
  for (std::size_t a = 0; a < 3; ++a) {
    const double centre = 0.5 * (b.lo[a] + b.hi[a]);
    const double half = 0.5 * (b.hi[a] - b.lo[a]) * scale + margin;
    b.lo[a] = centre - half;
    b.hi[a] = centre + half;
  }
  return b;
}

double squaredDistance(const Box3& box, const Point3& x) {
  double s = 0.0;
  for (std::size_t a = 0; a < 3; ++a) {
    const double d = std::max({box.lo[a] - x[a], x[a] - box.hi[a], 0.0});
    s += d * d;
  }
  return s;
}

MasterCellIndex::MasterCellIndex() : tree_(std::make_unique<Tree>()) {}
MasterCellIndex::~MasterCellIndex() = default;
MasterCellIndex::MasterCellIndex(MasterCellIndex&&) noexcept = default;
MasterCellIndex& MasterCellIndex::operator=(MasterCellIndex&&) noexcept = default;

void MasterCellIndex::build(const std::vector<Box3>& boxes) {
  std::vector<Value> values;
  values.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    values.emplace_back(toBoost(boxes[i]), static_cast<int>(i));
  }
  // The range constructor bulk-loads (packing): a balanced tree in O(n log n).
  tree_->rtree = bgi::rtree<Value, bgi::rstar<16>>(values.begin(), values.end());
}

std::size_t MasterCellIndex::size() const {
  return tree_->rtree.size();
}

void MasterCellIndex::query(const Box3& box, std::vector<int>& out) const {
  out.clear();
  tree_->rtree.query(bgi::intersects(toBoost(box)), PositionSink{&out});
}

void MasterCellIndex::queryAround(const Point3& x, double half, std::vector<int>& out) const {
  query(Box3{{x[0] - half, x[1] - half, x[2] - half}, {x[0] + half, x[1] + half, x[2] + half}}, out);
}

} // namespace stella::contact
