// Builds a structured hexahedral mesh of 100^3 cells (1,030,301 nodes) and reports the bytes the
// Mesh holds per node and per cell (groups aside), and the time to build it. The budget is
// 100 bytes per node and 200 bytes per linear cell (doc/bench/mesh-memory.md).

#include "solver/mesh/Mesh.hpp"

#include <benchmark/benchmark.h>

namespace {

stella::Mesh buildHexMesh(int n) {
  using stella::NodeId;
  stella::Mesh m;
  const int p = n + 1;
  m.reserveNodes(p * p * p);
  m.reserveCells(n * n * n, static_cast<std::size_t>(8) * n * n * n);
  for (int k = 0; k < p; ++k) {
    for (int j = 0; j < p; ++j) {
      for (int i = 0; i < p; ++i) {
        m.addNode({double(i) / n, double(j) / n, double(k) / n});
      }
    }
  }
  const auto id = [p](int i, int j, int k) { return static_cast<NodeId>((k * p + j) * p + i); };
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const NodeId c[] = {
            id(i, j, k),     id(i + 1, j, k),     id(i + 1, j + 1, k),     id(i, j + 1, k),
            id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        m.addCell(stella::CellType::HEXA8, c);
      }
    }
  }
  return m;
}

void BM_HexMeshMemory(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  double bytes = 0;
  double nodes = 0;
  double cells = 0;
  for (auto _ : state) {
    const stella::Mesh m = buildHexMesh(n);
    bytes = static_cast<double>(m.memoryBytes(false));
    nodes = m.nodeCount();
    cells = m.cellCount();
    benchmark::DoNotOptimize(bytes);
  }
  // Bytes per node counts the coordinates and node names; bytes per cell the connectivity,
  // offsets, types and cell names. Their sum is the mesh total.
  const double nodeBytes = 3 * sizeof(double) * nodes;
  state.counters["nodes"] = nodes;
  state.counters["cells"] = cells;
  state.counters["bytes_total"] = bytes;
  state.counters["bytes_per_node"] = nodeBytes / nodes;
  state.counters["bytes_per_cell"] = (bytes - nodeBytes) / cells;
  state.counters["total_per_node"] = bytes / nodes;
}

BENCHMARK(BM_HexMeshMemory)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace

BENCHMARK_MAIN();
