// Timing of mortar pairing in 3D (MortarFacePairing: R-tree search + polygon clipping) against
// the number of slave faces: a wavy surface of k x k QUAD4 slave faces and a non-matching master
// surface of TRIA3 faces (about 0.73 k x 0.73 k squares cut in two, over a 4 % wider square,
// 0.1 / k above, facing the slave). Per size: faces, candidate pairs, overlaps, the search time
// (boxes + R-tree build and queries), the pairing time (search + clipping + storage), us per
// slave face, the bytes of the result and the process's peak RSS, the covered fraction of the
// slave area; at small sizes the search with every pair of boxes tested (exhaustive) against the
// R-tree search, the pairing with that exhaustive search and with every master clipped against
// every slave (all pairs) against the R-tree pairing, and whether they agree. Times are CPU
// seconds of the process (1 thread unless asked). `points` = 0 stores only master and area per
// overlap (the integration points are still computed): the memory of 10^6 faces with points
// kept is about 6 GB.
// Usage: stella-bench-mortar [max_slave_faces=1100000] [max_brute_faces=4200] [threads=1]
//                            [points=1 (0: keep only master and area per overlap)]

#include "solver/contact/mortar/MortarFacePairing.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <numeric>
#include <string>
#include <vector>

using namespace stella;
using namespace stella::mortar;

namespace {

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double peakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0; // kB on Linux
}

Point3 wave(double x, double y, double z0) {
  return {x, y, z0 + 0.02 * std::sin(6.0 * x) * std::cos(5.0 * y)};
}

// k x k faces over [a, b]^2: QUAD4 with normals +z, or TRIA3 (two per square) with normals -z.
std::vector<Face> grid(int k, double a, double b, double z0, bool triangles) {
  const auto at = [&](int i, int j) { return wave(a + (b - a) * i / k, a + (b - a) * j / k, z0); };
  std::vector<Face> faces;
  faces.reserve(static_cast<std::size_t>(k) * static_cast<std::size_t>(k) * (triangles ? 2 : 1));
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < k; ++i) {
      const Point3 p0 = at(i, j), p1 = at(i + 1, j), p2 = at(i + 1, j + 1), p3 = at(i, j + 1);
      if (triangles) {
        faces.push_back({CellType::TRIA3, {p0, p2, p1}});
        faces.push_back({CellType::TRIA3, {p0, p3, p2}});
      } else {
        faces.push_back({CellType::QUAD4, {p0, p1, p2, p3}});
      }
    }
  }
  return faces;
}

double hullArea(const Face& f) {
  const std::size_t nv = f.type == CellType::TRIA3 ? 3 : 4;
  Point3 n{0, 0, 0};
  for (std::size_t i = 1; i + 1 < nv; ++i) {
    n = n + cross(f.nodes[i] - f.nodes[0], f.nodes[i + 1] - f.nodes[0]);
  }
  return 0.5 * norm(n);
}

bool same(const FacePairing& a, const FacePairing& b) {
  if (a.offsets != b.offsets || a.overlaps.size() != b.overlaps.size()) {
    return false;
  }
  for (std::size_t k = 0; k < a.overlaps.size(); ++k) {
    if (a.overlaps[k].master != b.overlaps[k].master || a.overlaps[k].area != b.overlaps[k].area) {
      return false;
    }
  }
  return true;
}

// Every master clipped against every slave (no search at all).
FacePairing allPairs(const std::vector<Face>& slaves, const std::vector<Face>& masters) {
  std::vector<int> every(masters.size());
  std::iota(every.begin(), every.end(), 0);
  FacePairing out;
  for (const auto& s : slaves) {
    for (const auto& o : intersectFaces(s, masters, every)) {
      out.overlaps.push_back({o.master, o.area, 0, o.points.size(), 0, o.polygon.size()});
    }
    out.offsets.push_back(out.overlaps.size());
  }
  return out;
}

} // namespace

int main(int argc, char** argv) {
  const long maxFaces = argc > 1 ? std::atol(argv[1]) : 1100000L;
  const long maxBrute = argc > 2 ? std::atol(argv[2]) : 4200L;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 1;
  const bool points = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  std::printf("threads %d, integration points %s\n\n", threads, points ? "kept" : "not kept");
  std::printf(
      "| slave faces | master faces | candidates | overlaps | search CPU (s) | exhaustive search CPU (s), x "
      "R-tree | pairing CPU (s) | us/face | result (MB) | peak RSS (MB) | covered / slave area | pairing "
      "with "
      "exhaustive search CPU (s), x R-tree | all pairs clipped CPU (s), x R-tree |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  double firstN = 0, firstT = 0, lastN = 0, lastT = 0;
  for (const int k : {32, 45, 64, 91, 128, 181, 256, 362, 512, 724, 1024}) {
    if (static_cast<long>(k) * k > maxFaces) {
      break;
    }
    const int km = std::max(2, static_cast<int>(0.73 * k));
    const auto slaves = grid(k, 0.0, 1.0, 0.0, false);
    // The gap is 0.1 of the slave faces' size (within the default margin, 0.25 of it): a fixed
    // gap would widen the search as the faces shrink below it (the candidates per slave face
    // doubled from 6.5e4 to 1.3e5 faces with a gap of 1e-3 and a margin of 2e-3).
    const auto masters = grid(km, -0.02, 1.02, 0.1 / k, true);
    FacePairingOptions options;
    options.threads = threads;
    options.keepPoints = points;
    options.keepPolygons = points;

    // The search alone: boxes, R-tree, queries; at small sizes every pair of boxes tested.
    double start = cpuSeconds();
    std::vector<contact::Box3> sb, mb;
    for (const auto& f : slaves) {
      sb.push_back(slaveBox(f.type, f.nodes.data(), 4, options.margin));
    }
    for (const auto& f : masters) {
      mb.push_back(slaveBox(f.type, f.nodes.data(), 3, {0.0, 0.0}));
    }
    const Candidates candidates = findCandidates(sb, mb);
    const double search = cpuSeconds() - start;
    std::string exhaustiveSearch = "-";
    if (static_cast<long>(slaves.size()) <= 4 * maxBrute) {
      start = cpuSeconds();
      const Candidates all = findCandidates(sb, mb, true);
      const double t = cpuSeconds() - start;
      exhaustiveSearch =
          std::to_string(t).substr(0, 6) + ", x " + std::to_string(t / search).substr(0, 5) +
          (all.offsets == candidates.offsets && all.masters == candidates.masters ? " (same)" : " (DIFFER)");
    }
    sb = {};
    mb = {};

    start = cpuSeconds();
    const FacePairing pairing = pairFaces(slaves, masters, options);
    const double cpu = cpuSeconds() - start;
    double covered = 0, area = 0;
    for (std::size_t s = 0; s < slaves.size(); ++s) {
      covered += pairing.coveredArea(s);
      area += hullArea(slaves[s]);
    }
    std::string exhaustive = "-", brute = "-";
    if (static_cast<long>(slaves.size()) <= 4 * maxBrute) {
      FacePairingOptions e = options;
      e.exhaustive = true;
      start = cpuSeconds();
      const FacePairing ex = pairFaces(slaves, masters, e);
      const double t = cpuSeconds() - start;
      exhaustive = std::to_string(t).substr(0, 6) + ", x " + std::to_string(t / cpu).substr(0, 5) +
                   (same(ex, pairing) ? " (same)" : " (DIFFER)");
    }
    if (static_cast<long>(slaves.size()) <= maxBrute) {
      start = cpuSeconds();
      const FacePairing all = allPairs(slaves, masters);
      const double t = cpuSeconds() - start;
      brute = std::to_string(t).substr(0, 6) + ", x " + std::to_string(t / cpu).substr(0, 5) +
              (same(all, pairing) ? " (same)" : " (DIFFER)");
    }
    const double n = static_cast<double>(slaves.size());
    std::printf("| %zu | %zu | %zu | %zu | %.4f | %s | %.3f | %.2f | %.1f | %.0f | %.12f | %s | %s |\n",
                slaves.size(), masters.size(), candidates.masters.size(), pairing.overlaps.size(), search,
                exhaustiveSearch.c_str(), cpu, 1e6 * cpu / n,
                static_cast<double>(pairing.bytes()) / 1048576.0, peakRssMb(), covered / area,
                exhaustive.c_str(), brute.c_str());
    std::fflush(stdout);
    if (firstN == 0) {
      firstN = n;
      firstT = cpu;
    }
    lastN = n;
    lastT = cpu;
  }
  if (lastN > firstN) {
    std::printf("\nlog-log slope of the pairing CPU time vs slave faces (%.0f to %.0f): %.3f\n", firstN,
                lastN, std::log(lastT / firstT) / std::log(lastN / firstN));
  }
  return 0;
}
