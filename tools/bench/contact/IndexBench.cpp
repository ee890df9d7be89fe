// The measurement behind the choice of the pairing's spatial index (doc/contact.md): the query
// the exact pairing makes for every slave node, "the master cells that may hold a point within
// distance d of x", answered by
//   - the Boost.Geometry R-tree of the cells' boxes (MasterCellIndex: cube query, then the
//     boxes' Euclidean distance), and
//   - a nanoflann kd-tree of the master nodes (a point tree: radius search with d + the largest
//     cell radius, the cells around the nodes found, then the same box filter).
// On the benchmark's wavy QUAD4 master (k x k cells) and k x k query points 0.01 above it.
// Times are CPU times of the thread. Usage: stella-bench-contact-index [k=512] [d=0.0105]

#include "solver/contact/MasterSurface.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <nanoflann.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

using namespace stella;

namespace {

struct Cloud {
  std::vector<Point3> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t a) const { return points[i][a]; }
  template <class Box> bool kdtree_get_bbox(Box&) const { return false; }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Cloud>, Cloud, 3>;

// CPU time of this thread: the machine may be shared, and the comparison is per core.
double cpuNow() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double since(double start) {
  return cpuNow() - start;
}

double wave(double x, double y) {
  return 0.02 * std::sin(6.0 * x) * std::cos(5.0 * y);
}

} // namespace

int main(int argc, char** argv) {
  const int k = argc > 1 ? std::atoi(argv[1]) : 512;
  const double d = argc > 2 ? std::atof(argv[2]) : 0.0105;
  Mesh mesh;
  mesh.setDimension(3);
  for (int j = 0; j <= k; ++j) {
    for (int i = 0; i <= k; ++i) {
      const double x = static_cast<double>(i) / k;
      const double y = static_cast<double>(j) / k;
      mesh.addNode({x, y, wave(x, y)});
    }
  }
  std::vector<CellId> cells;
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < k; ++i) {
      const NodeId a = j * (k + 1) + i;
      cells.push_back(mesh.addCell(CellType::QUAD4, std::vector<NodeId>{a, a + 1, a + k + 2, a + k + 1}));
    }
  }
  std::vector<Point3> queries;
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < k; ++i) {
      const double x = (i + 0.37) / k;
      const double y = (j + 0.61) / k;
      queries.push_back({x, y, wave(x, y) + 0.01});
    }
  }
  contact::MasterSurface surface(mesh, cells, 2);
  const auto position = [&mesh](NodeId n) { return mesh.point(n); };

  double start = cpuNow();
  surface.update(position, true, 0.0, false);
  const double rtreeBuild = since(start);
  double radius = 0.0; // largest distance from a cell's node to its box centre
  for (int c = 0; c < surface.cellCount(); ++c) {
    const auto& b = surface.box(c);
    radius = std::max(radius, 0.5 * norm(b.hi - b.lo));
  }

  std::vector<int> found;
  std::vector<std::uint32_t> stamp(cells.size(), 0);
  std::uint32_t epoch = 0;
  long rtreeCandidates = 0;
  long rtreeKept = 0;
  start = cpuNow();
  for (const Point3& x : queries) {
    surface.index().queryAround(x, d, found);
    rtreeCandidates += static_cast<long>(found.size());
    for (int c : found) {
      rtreeKept += contact::squaredDistance(surface.box(c), x) <= d * d ? 1 : 0;
    }
  }
  const double rtreeQuery = since(start);

  Cloud cloud;
  for (int l = 0; l < surface.nodeCount(); ++l) {
    cloud.points.push_back(surface.position(l));
  }
  start = cpuNow();
  KdTree kd(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  kd.buildIndex();
  const double kdBuild = since(start);
  std::vector<std::pair<unsigned, double>> matches;
  long kdNodes = 0;
  long kdCandidates = 0;
  long kdKept = 0;
  const double r = d + radius;
  start = cpuNow();
  for (const Point3& x : queries) {
    ++epoch;
    kd.radiusSearch(x.data(), r * r, matches, nanoflann::SearchParams());
    kdNodes += static_cast<long>(matches.size());
    for (const auto& [node, dist] : matches) {
      for (int c : surface.cellsOfNode(static_cast<int>(node))) {
        if (stamp[static_cast<std::size_t>(c)] != epoch) {
          stamp[static_cast<std::size_t>(c)] = epoch;
          ++kdCandidates;
          kdKept += contact::squaredDistance(surface.box(c), x) <= d * d ? 1 : 0;
        }
      }
    }
  }
  const double kdQuery = since(start);
  const double q = static_cast<double>(queries.size());
  std::printf("%d cells, %zu queries, d = %g (largest cell radius %.3g)\n", k * k, queries.size(), d, radius);
  std::printf("| index | build (s) | query us/point | cells found per point | cells kept (box within d) |\n");
  std::printf("|---|---|---|---|---|\n");
  std::printf("| Boost.Geometry R-tree of cell boxes | %.3f | %.3f | %.1f | %.2f |\n", rtreeBuild,
              1e6 * rtreeQuery / q, static_cast<double>(rtreeCandidates) / q,
              static_cast<double>(rtreeKept) / q);
  std::printf("| nanoflann kd-tree of master nodes | %.3f | %.3f | %.1f (%.1f nodes) | %.2f |\n", kdBuild,
              1e6 * kdQuery / q, static_cast<double>(kdCandidates) / q, static_cast<double>(kdNodes) / q,
              static_cast<double>(kdKept) / q);
  return 0;
}
