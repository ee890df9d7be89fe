// Static kd-tree over points: median splits on the axis of largest spread, nearest-neighbour
// queries by branch-and-bound.

#include "tools/bench/contact/PointSearchTree.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <queue>

namespace stella::contact::legacy {

namespace {

double squaredDistance(const Point3& a, const Point3& b) {
  const double dx = a[0] - b[0];
  const double dy = a[1] - b[1];
  const double dz = a[2] - b[2];
  return dx * dx + dy * dy + dz * dz;
}

} // namespace

PointSearchTree::PointSearchTree(std::vector<Point3> points) : points_(std::move(points)) {
  order_.resize(points_.size());
  std::iota(order_.begin(), order_.end(), 0);
  axis_.assign(points_.size(), 0);
  build(0, static_cast<int>(points_.size()), 0);
}

void PointSearchTree::build(int begin, int end, int depth) {
  if (end - begin <= 1) {
    return;
  }
  Point3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
            std::numeric_limits<double>::max()};
  Point3 hi{-lo[0], -lo[1], -lo[2]};
  for (int i = begin; i < end; ++i) {
    const auto& p = points_[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])];
    for (int a = 0; a < 3; ++a) {
      lo[static_cast<std::size_t>(a)] =
          std::min(lo[static_cast<std::size_t>(a)], p[static_cast<std::size_t>(a)]);
      hi[static_cast<std::size_t>(a)] =
          std::max(hi[static_cast<std::size_t>(a)], p[static_cast<std::size_t>(a)]);
    }
  }
  int axis = 0;
  for (int a = 1; a < 3; ++a) {
    if (hi[static_cast<std::size_t>(a)] - lo[static_cast<std::size_t>(a)] >
        hi[static_cast<std::size_t>(axis)] - lo[static_cast<std::size_t>(axis)]) {
      axis = a;
    }
  }
  const int mid = (begin + end) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](int a, int b) {
    return points_[static_cast<std::size_t>(a)][static_cast<std::size_t>(axis)] <
           points_[static_cast<std::size_t>(b)][static_cast<std::size_t>(axis)];
  });
  axis_[static_cast<std::size_t>(mid)] = static_cast<signed char>(axis);
  build(begin, mid, depth + 1);
  build(mid + 1, end, depth + 1);
}

std::vector<int> PointSearchTree::nearest(const Point3& x, int k) const {
  // Max-heap of the k best (distance, index).
  std::priority_queue<std::pair<double, int>> best;
  auto visit = [&](auto&& self, int begin, int end) -> void {
    if (begin >= end) {
      return;
    }
    const int mid = (begin + end) / 2;
    const int idx = order_[static_cast<std::size_t>(mid)];
    const Point3& p = points_[static_cast<std::size_t>(idx)];
    const double d2 = squaredDistance(x, p);
    if (static_cast<int>(best.size()) < k) {
      best.emplace(d2, idx);
    } else if (d2 < best.top().first) {
      best.pop();
      best.emplace(d2, idx);
    }
    if (end - begin == 1) {
      return;
    }
    const auto axis = static_cast<std::size_t>(axis_[static_cast<std::size_t>(mid)]);
    const double delta = x[axis] - p[axis];
    const bool leftFirst = delta < 0.0;
    if (leftFirst) {
      self(self, begin, mid);
    } else {
      self(self, mid + 1, end);
    }
    if (static_cast<int>(best.size()) < k || delta * delta < best.top().first) {
      if (leftFirst) {
        self(self, mid + 1, end);
      } else {
        self(self, begin, mid);
      }
    }
  };
  visit(visit, 0, static_cast<int>(points_.size()));
  std::vector<int> out(best.size());
  for (std::size_t i = out.size(); i-- > 0;) {
    out[i] = best.top().second;
    best.pop();
  }
  return out;
}

int PointSearchTree::nearest(const Point3& x) const {
  if (points_.empty()) {
    return -1;
  }
  return nearest(x, 1).front();
}

} // namespace stella::contact::legacy
