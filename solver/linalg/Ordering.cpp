// Reverse Cuthill-McKee ordering (see Ordering.hpp).

#include "solver/linalg/Ordering.hpp"

#include <algorithm>
#include <cstdlib>

namespace stella::linalg {
namespace {

using Graph = std::vector<std::vector<int>>;

Graph symmetricGraph(const SparsePattern& p) {
  Graph g(static_cast<std::size_t>(p.size));
  for (int i = 0; i < p.size; ++i) {
    for (auto k = p.rowStart[static_cast<std::size_t>(i)]; k < p.rowStart[static_cast<std::size_t>(i) + 1];
         ++k) {
      const int j = p.columns[static_cast<std::size_t>(k)];
      if (j != i) {
        g[static_cast<std::size_t>(i)].push_back(j);
        if (p.storage == Storage::Upper) {
          g[static_cast<std::size_t>(j)].push_back(i);
        }
      }
    }
  }
  for (auto& row : g) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
  }
  return g;
}

// Breadth-first levels from `root` over the unvisited nodes; returns the nodes in visit order
// (neighbours by increasing degree) and the last level's node of smallest degree in `far`.
std::vector<int> levelOrder(const Graph& g, int root, const std::vector<char>& done, int& far, int& depth) {
  std::vector<int> order{root}, level(g.size(), -1);
  level[static_cast<std::size_t>(root)] = 0;
  std::vector<int> next;
  for (std::size_t head = 0; head < order.size(); ++head) {
    const int v = order[head];
    next.clear();
    for (int w : g[static_cast<std::size_t>(v)]) {
      if (done[static_cast<std::size_t>(w)] == 0 && level[static_cast<std::size_t>(w)] < 0) {
        level[static_cast<std::size_t>(w)] = level[static_cast<std::size_t>(v)] + 1;
        next.push_back(w);
      }
    }
    std::stable_sort(next.begin(), next.end(), [&](int a, int b) {
      return g[static_cast<std::size_t>(a)].size() < g[static_cast<std::size_t>(b)].size();
    });
    order.insert(order.end(), next.begin(), next.end());
  }
  depth = level[static_cast<std::size_t>(order.back())];
  far = order.back();
  for (int v : order) {
    if (level[static_cast<std::size_t>(v)] == depth &&
        g[static_cast<std::size_t>(v)].size() < g[static_cast<std::size_t>(far)].size()) {
      far = v;
    }
  }
  return order;
}

} // namespace

std::vector<int> reverseCuthillMcKee(const SparsePattern& p) {
  const Graph g = symmetricGraph(p);
  std::vector<char> done(g.size(), 0);
  std::vector<int> result;
  result.reserve(g.size());
  for (int start = 0; start < p.size; ++start) {
    if (done[static_cast<std::size_t>(start)] != 0) {
      continue;
    }
    int root = start, far = start, depth = 0, lastDepth = -1;
    std::vector<int> order = levelOrder(g, root, done, far, depth);
    for (int sweep = 0; sweep < 8 && depth > lastDepth; ++sweep) { // pseudo-peripheral root
      lastDepth = depth;
      int candidateFar = far, candidateDepth = 0;
      std::vector<int> candidate = levelOrder(g, far, done, candidateFar, candidateDepth);
      if (candidateDepth <= lastDepth) {
        break;
      }
      root = far;
      order = std::move(candidate);
      far = candidateFar;
      depth = candidateDepth;
    }
    for (int v : order) {
      done[static_cast<std::size_t>(v)] = 1;
    }
    result.insert(result.end(), order.begin(), order.end());
  }
  std::reverse(result.begin(), result.end());
  return result;
}

int bandwidth(const SparsePattern& p, const std::vector<int>& order) {
  std::vector<int> position(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    position[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
  }
  int width = 0;
  for (int i = 0; i < p.size; ++i) {
    for (auto k = p.rowStart[static_cast<std::size_t>(i)]; k < p.rowStart[static_cast<std::size_t>(i) + 1];
         ++k) {
      const int j = p.columns[static_cast<std::size_t>(k)];
      width = std::max(
          width, std::abs(position[static_cast<std::size_t>(i)] - position[static_cast<std::size_t>(j)]));
    }
  }
  return width;
}

} // namespace stella::linalg
