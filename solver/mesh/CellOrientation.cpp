// Consistent orientation of shells and lines (see CellOrientation.hpp): a breadth-first walk
// over the shared edges (faces) or nodes (segments) deciding, cell by cell, whether it must be
// reversed relative to the reference cell of its connected set.

#include "solver/mesh/CellOrientation.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/mesh/MeshTransform.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

namespace stella {

namespace {

// A shared piece of a cell's boundary (an edge as its sorted vertex pair, or a node) and the
// direction the cell runs through it (+1 / -1).
struct Piece {
  std::pair<NodeId, NodeId> key;
  int sign;
};

std::vector<Piece> facePieces(const Mesh& m, CellId c) {
  const auto n = m.cellNodes(c);
  const int nv = vertexCount(m.cellType(c));
  std::vector<Piece> p;
  for (int i = 0; i < nv; ++i) {
    const NodeId a = n[static_cast<std::size_t>(i)];
    const NodeId b = n[static_cast<std::size_t>((i + 1) % nv)];
    p.push_back({{std::min(a, b), std::max(a, b)}, a < b ? 1 : -1});
  }
  return p;
}

std::vector<Piece> linePieces(const Mesh& m, CellId c) {
  const auto n = m.cellNodes(c);
  return {{{n[0], n[0]}, -1}, {{n[1], n[1]}, 1}}; // starts at node 0, ends at node 1
}

[[noreturn]] void cannotOrient(const Mesh& m, CellId a, CellId b, const char* what) {
  throw UserError(
      msg::make("ORIE_1", {{"cell_name", m.cellName(a)}, {"cell_name_2", m.cellName(b)}, {"what", what}}));
}

using PiecesOf = std::vector<Piece> (*)(const Mesh&, CellId);
using VectorOf = Point3 (*)(const Mesh&, CellId);

Point3 segmentTangent(const Mesh& m, CellId c) {
  const auto n = m.cellNodes(c);
  return m.point(n[1]) - m.point(n[0]);
}

OrientationSummary orient(Mesh& m, const std::vector<CellId>& cells, PiecesOf pieces, VectorOf vectorOf,
                          const std::optional<Point3>& direction, std::optional<NodeId> node) {
  std::map<std::pair<NodeId, NodeId>, std::vector<std::pair<std::size_t, int>>> byKey;
  std::vector<std::vector<Piece>> cellPieces;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    cellPieces.push_back(pieces(m, cells[i]));
    for (const auto& p : cellPieces.back()) {
      byKey[p.key].emplace_back(i, p.sign);
    }
  }
  std::vector<int> flip(cells.size(), -1); // -1 unvisited, 0 keep, 1 reverse (relative)
  OrientationSummary summary;
  for (std::size_t seed = 0; seed < cells.size(); ++seed) {
    if (flip[seed] >= 0) {
      continue;
    }
    ++summary.components;
    std::vector<std::size_t> members{seed};
    flip[seed] = 0;
    std::deque<std::size_t> queue{seed};
    while (!queue.empty()) {
      const std::size_t i = queue.front();
      queue.pop_front();
      for (const auto& p : cellPieces[i]) {
        const auto& sharing = byKey[p.key];
        if (sharing.size() > 2) {
          cannotOrient(m, cells[sharing[0].first], cells[sharing[2].first],
                       "and others meet on one edge or node");
        }
        const int effective = flip[i] != 0 ? -p.sign : p.sign;
        for (const auto& [j, sign] : sharing) {
          if (j == i) {
            continue;
          }
          const int wanted = sign == -effective ? 0 : 1;
          if (flip[j] < 0) {
            flip[j] = wanted;
            members.push_back(j);
            queue.push_back(j);
          } else if (flip[j] != wanted) {
            cannotOrient(m, cells[i], cells[j], "would need opposite orientations (a Moebius band?)");
          }
        }
      }
    }
    // The reference cell of this set and whether the whole set must be turned over.
    bool turn = false;
    if (direction) {
      // The member (holding `node`, when the set holds it) most nearly parallel to the direction.
      const auto holds = [&](std::size_t i) {
        const auto n = m.cellNodes(cells[i]);
        return node && std::find(n.begin(), n.end(), *node) != n.end();
      };
      const bool anyHolds = std::any_of(members.begin(), members.end(), holds);
      std::size_t reference = seed;
      double best = -1.0;
      for (const std::size_t i : members) {
        if (anyHolds && !holds(i)) {
          continue;
        }
        const Point3 v = vectorOf(m, cells[i]);
        const double size = norm(v) * norm(*direction);
        const double cosine = size > 0.0 ? std::abs(dot(v, *direction)) / size : 0.0;
        if (cosine > best + 1e-12) {
          best = cosine;
          reference = i;
        }
      }
      const double along = dot(vectorOf(m, cells[reference]), *direction);
      turn = (flip[reference] != 0 ? -along : along) < 0.0;
    }
    for (const std::size_t i : members) {
      if ((flip[i] != 0) != turn) {
        reverseCell(m, cells[i]);
        ++summary.reversed;
      }
    }
  }
  return summary;
}

void checkDimension(const Mesh& m, const std::vector<CellId>& cells, int dim, const char* what) {
  for (const CellId c : cells) {
    if (dimension(m.cellType(c)) != dim) {
      throw UserError(msg::make(
          "ORIE_2",
          {{"cell_name", m.cellName(c)}, {"name", std::string(name(m.cellType(c)))}, {"what", what}}));
    }
  }
}

std::vector<Piece> piecesOf(const Mesh& m, CellId c) {
  return dimension(m.cellType(c)) == 1 ? linePieces(m, c) : facePieces(m, c);
}

} // namespace

OrientationSummary propagateOrientation(Mesh& mesh, const std::vector<CellId>& cells,
                                        const std::vector<bool>& fixed, std::vector<CellId>& unanchored) {
  std::map<std::pair<NodeId, NodeId>, std::vector<std::pair<std::size_t, int>>> byKey;
  std::vector<std::vector<Piece>> cellPieces;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    cellPieces.push_back(piecesOf(mesh, cells[i]));
    for (const auto& p : cellPieces.back()) {
      byKey[p.key].emplace_back(i, p.sign);
    }
  }
  std::vector<int> flip(cells.size(), -1); // -1 unvisited, 0 keep, 1 reverse
  OrientationSummary summary;
  const auto walk = [&](std::deque<std::size_t> queue) {
    while (!queue.empty()) {
      const std::size_t i = queue.front();
      queue.pop_front();
      for (const auto& p : cellPieces[i]) {
        const int effective = flip[i] != 0 ? -p.sign : p.sign;
        for (const auto& [j, sign] : byKey[p.key]) {
          if (flip[j] < 0) {
            flip[j] = sign == -effective ? 0 : 1;
            queue.push_back(j);
          }
        }
      }
    }
  };
  std::deque<std::size_t> anchored;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (fixed[i]) {
      flip[i] = 0;
      anchored.push_back(i);
    }
  }
  if (!anchored.empty()) {
    ++summary.components; // the anchored sets, counted as one
  }
  walk(anchored);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (flip[i] < 0) {
      unanchored.push_back(cells[i]); // reached from no fixed cell
    }
  }
  for (std::size_t seed = 0; seed < cells.size(); ++seed) {
    if (flip[seed] < 0) {
      ++summary.components;
      flip[seed] = 0;
      walk({seed});
    }
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (flip[i] == 1) {
      reverseCell(mesh, cells[i]);
      ++summary.reversed;
    }
  }
  return summary;
}

OrientationSummary orientShells(Mesh& mesh, const std::vector<CellId>& faces,
                                const std::optional<Point3>& direction, std::optional<NodeId> node) {
  checkDimension(mesh, faces, 2, "shell (surface) cell");
  return orient(mesh, faces, facePieces, cellNormal, direction, node);
}

OrientationSummary orientLines(Mesh& mesh, const std::vector<CellId>& segments,
                               const std::optional<Point3>& direction, std::optional<NodeId> node) {
  checkDimension(mesh, segments, 1, "line (segment) cell");
  return orient(mesh, segments, linePieces, segmentTangent, direction, node);
}

} // namespace stella
