// Timing of contact pairing (MAIT_ESCL projection) against the number of slave nodes: a wavy
// 3D master surface of QUAD4 faces and a finer slave surface above it, from 10^3 up to the
// given maximum of slave nodes (default 10^6). Prints one line per size and the log-log slope.
// Usage: stella-bench-contact [max_slave_nodes]

#include "solver/contact/ContactPairing.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace stella;

namespace {

// A k x k grid of QUAD4 faces over [0,1]^2 at height z(x, y); returns the cell ids.
std::vector<CellId> grid(Mesh& mesh, int k, double z0, bool flip) {
  const NodeId base = mesh.nodeCount();
  for (int j = 0; j <= k; ++j) {
    for (int i = 0; i <= k; ++i) {
      const double x = static_cast<double>(i) / k;
      const double y = static_cast<double>(j) / k;
      mesh.addNode({x, y, z0 + 0.02 * std::sin(6.0 * x) * std::cos(5.0 * y)});
    }
  }
  std::vector<CellId> cells;
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < k; ++i) {
      const NodeId a = base + j * (k + 1) + i;
      std::vector<NodeId> q{a, a + 1, a + k + 2, a + k + 1};
      if (flip) {
        std::swap(q[1], q[3]);
      }
      cells.push_back(mesh.addCell(CellType::QUAD4, q));
    }
  }
  return cells;
}

} // namespace

int main(int argc, char** argv) {
  const long maxNodes = argc > 1 ? std::atol(argv[1]) : 1000000L;
  std::printf("%12s %12s %12s %14s %14s\n", "slave_nodes", "master_nodes", "pairing_s", "us_per_node",
              "status");
  double firstN = 0.0;
  double firstT = 0.0;
  double lastN = 0.0;
  double lastT = 0.0;
  for (int ks = 31; static_cast<long>(ks + 1) * (ks + 1) <= maxNodes; ks = ks * 2 + 1) {
    Mesh mesh;
    mesh.setDimension(3);
    const int km = ks / 2 + 1;
    mesh.setCellGroup("MASTER", grid(mesh, km, 0.0, false));
    mesh.setCellGroup("SLAVE", grid(mesh, ks, 0.01, true));
    contact::ContactZone zone;
    zone.masterGroup = "MASTER";
    zone.slaveGroup = "SLAVE";
    contact::PairingOptions options;
    options.dimension = 3;
    const auto start = std::chrono::steady_clock::now();
    const auto links = contact::pairZone(mesh, contact::meshPositions(mesh, nullptr), 0, zone, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double worst = 0.0;
    for (const auto& l : links) {
      worst = std::max(worst, l.paired ? 0.0 : 1.0);
    }
    const double n = static_cast<double>(links.size());
    std::printf("%12zu %12d %12.3f %14.3f %14s\n", links.size(), (km + 1) * (km + 1), seconds,
                1e6 * seconds / n, worst > 0 ? "unpaired!" : "all paired");
    std::fflush(stdout);
    if (firstN == 0.0) {
      firstN = n;
      firstT = seconds;
    }
    lastN = n;
    lastT = seconds;
  }
  if (lastN > firstN) {
    std::printf("log-log slope of time vs slave nodes: %.3f\n",
                std::log(lastT / firstT) / std::log(lastN / firstN));
  }
  return 0;
}
