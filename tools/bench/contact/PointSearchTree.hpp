#pragma once
// A static kd-tree over a set of points (the master nodes of a contact zone): built once in
// O(n log n), nearest-point queries in O(log n) on average. Used by the pairing so that its cost
// grows like n log n in the number of slave and master nodes.

#include "solver/mesh/Mesh.hpp"

#include <vector>

namespace stella::contact::legacy {

class PointSearchTree {
public:
  PointSearchTree() = default;
  explicit PointSearchTree(std::vector<Point3> points);
  bool empty() const { return points_.empty(); }
  // Index (into the constructor's array) of the point nearest to x; -1 when empty.
  int nearest(const Point3& x) const;
  // Indices of the k nearest points, nearest first.
  std::vector<int> nearest(const Point3& x, int k) const;

private:
  void build(int begin, int end, int depth);
  std::vector<Point3> points_;
  std::vector<int> order_; // tree order: the median of [b, e) at (b + e) / 2
  std::vector<signed char> axis_;
};

} // namespace stella::contact::legacy
