// Timing of contact pairing (MAIT_ESCL projection) against the number of slave nodes: a wavy 3D
// master surface of QUAD4 faces and a finer slave surface 0.01 above it, inset by 0.01 from the
// master's edges so that every slave node has an admissible orthogonal projection (on the
// master's full extent, the boundary nodes' projections fall outside the boundary cells by
// 0.01 |slope| ~ 0.0011, more than TOLE_PROJ_EXT = 0.5 parametric once the master cells are
// under 0.0045 wide: those nodes are rightly unpaired). Per size: the pairing before issue 23
// ("old", up to a size limit), the current pairing from scratch and re-pairing after a small
// displacement (warm start), on 1 and 2 threads; "all paired" or the count of unpaired nodes;
// a sample of slave cells paired again by brute force (every master cell tried) must agree.
// Usage: stella-bench-contact [max_slave_nodes=1100000] [max_old_slave_nodes=300000]

#include "solver/contact/ContactPairing.hpp"
#include "tools/bench/contact/LegacyPairing.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

using namespace stella;

namespace {

// A k x k grid of QUAD4 faces over [a, b]^2 at height z0 + the wave, normals towards +z; returns
// the cell ids.
std::vector<CellId> grid(Mesh& mesh, int k, double a, double b, double z0) {
  const NodeId base = mesh.nodeCount();
  for (int j = 0; j <= k; ++j) {
    for (int i = 0; i <= k; ++i) {
      const double x = a + (b - a) * i / k;
      const double y = a + (b - a) * j / k;
      mesh.addNode({x, y, z0 + 0.02 * std::sin(6.0 * x) * std::cos(5.0 * y)});
    }
  }
  std::vector<CellId> cells;
  for (int j = 0; j < k; ++j) {
    for (int i = 0; i < k; ++i) {
      const NodeId c = base + j * (k + 1) + i;
      cells.push_back(mesh.addCell(CellType::QUAD4, std::vector<NodeId>{c, c + 1, c + k + 2, c + k + 1}));
    }
  }
  return cells;
}

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// CPU time of the process (all threads): on a loaded machine the one-thread cost per core.
double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

int unpaired(const std::vector<contact::ContactLink>& links) {
  int n = 0;
  for (const auto& l : links) {
    n += l.paired ? 0 : 1;
  }
  return n;
}

// Slave nodes whose master cell differs between two pairings of the same nodes.
int differences(const std::vector<contact::ContactLink>& a, const std::vector<contact::ContactLink>& b) {
  int n = 0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    n += (a[k].paired != b[k].paired || a[k].masterCell != b[k].masterCell ||
          std::abs(a[k].gap - b[k].gap) > 1e-12 * std::max(std::abs(b[k].gap), 1e-3))
             ? 1
             : 0;
  }
  return n;
}

} // namespace

int main(int argc, char** argv) {
  const long maxNodes = argc > 1 ? std::atol(argv[1]) : 1100000L;
  const long maxOld = argc > 2 ? std::atol(argv[2]) : 300000L;
  std::printf("| slave nodes | master cells | old CPU (s) | new CPU (s) | us/node | re-pair CPU (s) | "
              "re-pair us/node | "
              "re-pair searched | wall 1 thread: first / re-pair (s) | wall 2 threads: first / re-pair (s) | "
              "status | "
              "brute-force sample |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  double firstN = 0.0;
  double firstT = 0.0;
  double lastN = 0.0;
  double lastT = 0.0;
  for (int ks = 31; static_cast<long>(ks + 1) * (ks + 1) <= maxNodes; ks = ks * 2 + 1) {
    Mesh mesh;
    mesh.setDimension(3);
    const int km = ks / 2 + 1;
    const auto master = grid(mesh, km, 0.0, 1.0, 0.0);
    const auto slave = grid(mesh, ks, 0.01, 0.99, 0.01);
    mesh.setCellGroup("MASTER", master);
    mesh.setCellGroup("SLAVE", slave);
    // A sample of about 32 slave cells for the brute-force check.
    std::vector<CellId> sample;
    for (std::size_t c = 0; c < slave.size(); c += std::max<std::size_t>(1, slave.size() / 32)) {
      sample.push_back(slave[c]);
    }
    mesh.setCellGroup("SAMPLE", sample);
    contact::ContactZone zone;
    zone.masterGroup = "MASTER";
    zone.slaveGroup = "SLAVE";
    contact::PairingOptions options;
    options.dimension = 3;
    const auto initial = contact::meshPositions(mesh, nullptr);
    // The small displacement of a geometric iteration: slave slides 0.3 x 0.2 of its spacing.
    std::vector<double> u(static_cast<std::size_t>(mesh.nodeCount()) * 3, 0.0);
    const NodeId firstSlave = mesh.cellNodes(slave.front())[0];
    for (NodeId n = firstSlave; n < mesh.nodeCount(); ++n) {
      u[static_cast<std::size_t>(n) * 3] = 0.3 * 0.98 / ks;
      u[static_cast<std::size_t>(n) * 3 + 1] = 0.2 * 0.98 / ks;
      u[static_cast<std::size_t>(n) * 3 + 2] = -0.002;
    }
    const auto moved = contact::meshPositions(mesh, &u);

    double oldSeconds = -1.0;
    std::vector<contact::ContactLink> old;
    if (static_cast<long>(ks + 1) * (ks + 1) <= maxOld) {
      const double start = cpuSeconds();
      old = contact::legacy::pairZone(mesh, initial, 0, zone, options);
      oldSeconds = cpuSeconds() - start;
    }
    double t[2][2] = {{0, 0}, {0, 0}}; // [threads - 1][first, re-pair]
    double cpu[2] = {0, 0};            // one thread: first, re-pair
    long searched = 0;
    std::vector<contact::ContactLink> first;
    std::vector<contact::ContactLink> second;
    for (int threads = 1; threads <= 2; ++threads) {
      options.threads = threads;
      contact::ZonePairing pairing(mesh, 0, zone, options);
      auto start = std::chrono::steady_clock::now();
      double cpuStart = cpuSeconds();
      pairing.pair(initial);
      t[threads - 1][0] = seconds(start);
      cpu[0] = threads == 1 ? cpuSeconds() - cpuStart : cpu[0];
      if (threads == 1) {
        first = pairing.links();
      } else if (differences(first, pairing.links()) != 0) {
        std::printf("2 threads differ from 1!\n");
      }
      start = std::chrono::steady_clock::now();
      cpuStart = cpuSeconds();
      pairing.pair(moved);
      t[threads - 1][1] = seconds(start);
      cpu[1] = threads == 1 ? cpuSeconds() - cpuStart : cpu[1];
      if (threads == 1) {
        second = pairing.links();
        searched = pairing.searchedNodes();
      } else if (differences(second, pairing.links()) != 0) {
        std::printf("2 threads differ from 1 at re-pairing!\n");
      }
    }
    // Brute force on the sample, at the initial and the moved positions.
    contact::ContactZone sampled = zone;
    sampled.slaveGroup = "SAMPLE";
    contact::PairingOptions brute;
    brute.exhaustive = true;
    int disagree = 0;
    int checked = 0;
    for (int pass = 0; pass < 2; ++pass) {
      const auto& all = pass == 0 ? first : second;
      const auto ref = contact::pairZone(mesh, pass == 0 ? initial : moved, 0, sampled, brute);
      // Slave links are in ascending node order: match by node.
      std::size_t k = 0;
      for (const auto& r : ref) {
        while (k < all.size() && all[k].slave < r.slave) {
          ++k;
        }
        disagree += differences({all[k]}, {r});
        ++checked;
      }
    }
    const int bad = unpaired(first) + unpaired(second);
    const double n = static_cast<double>(first.size());
    std::string oldText = oldSeconds < 0 ? "-" : std::to_string(oldSeconds).substr(0, 6);
    if (oldSeconds >= 0 && differences(old, first) != 0) {
      oldText += " (" + std::to_string(differences(old, first)) + " differ)";
    }
    std::printf("| %zu | %zu | %s | %.3f | %.2f | %.3f | %.2f | %ld | %.3f / %.3f | %.3f / %.3f | %s | %d/%d "
                "agree |\n",
                first.size(), master.size(), oldText.c_str(), cpu[0], 1e6 * cpu[0] / n, cpu[1],
                1e6 * cpu[1] / n, searched, t[0][0], t[0][1], t[1][0], t[1][1],
                bad == 0 ? "all paired" : (std::to_string(bad) + " unpaired!").c_str(), checked - disagree,
                checked);
    std::fflush(stdout);
    if (firstN == 0.0) {
      firstN = n;
      firstT = cpu[0];
    }
    lastN = n;
    lastT = cpu[0];
  }
  if (lastN > firstN) {
    std::printf("log-log slope of the first pairing's CPU time (1 thread) vs slave nodes: %.3f\n",
                std::log(lastT / firstT) / std::log(lastN / firstN));
  }
  return 0;
}
