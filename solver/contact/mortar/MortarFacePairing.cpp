// Mortar pairing in 3D (see MortarFacePairing.hpp).

#include "solver/contact/mortar/MortarFacePairing.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <thread>

namespace stella::mortar {

namespace {

bool isFace(CellType t) {
  switch (t) {
  case CellType::TRIA3:
  case CellType::TRIA6:
  case CellType::TRIA7:
  case CellType::QUAD4:
  case CellType::QUAD8:
  case CellType::QUAD9:
    return true;
  default:
    return false;
  }
}

void checkFaces(std::span<const Face> faces, const char* what) {
  for (const auto& f : faces) {
    STELLA_ASSERT(isFace(f.type) && static_cast<int>(f.nodes.size()) == nodeCount(f.type), what);
  }
}

std::vector<contact::Box3> boxes(std::span<const Face> faces, const SearchMargin& margin) {
  std::vector<contact::Box3> out;
  out.reserve(faces.size());
  for (const auto& f : faces) {
    out.push_back(slaveBox(f.type, f.nodes.data(), static_cast<int>(f.nodes.size()), margin));
  }
  return out;
}

// A slave face without a plane: its vertices' Newell normal vanishes next to its size squared
// (the kernel would divide by it).
bool degenerate(const Face& f) {
  const int nv = vertexCount(f.type);
  Point3 n{0, 0, 0};
  double h = 0;
  for (int i = 0; i < nv; ++i) {
    const Point3& a = f.nodes[static_cast<std::size_t>(i)];
    const Point3& b = f.nodes[static_cast<std::size_t>((i + 1) % nv)];
    n = n + cross(a - f.nodes[0], b - f.nodes[0]);
    h = std::max(h, norm(b - a));
  }
  return !(norm(n) > 1e-12 * h * h);
}

// Pairs slaves [begin, end) into `out` (its offsets start at 0 for `begin`).
void pairRange(std::span<const Face> slaves, std::span<const Face> masters, const Candidates& candidates,
               const FacePairingOptions& options, std::size_t begin, std::size_t end, FacePairing& out) {
  for (std::size_t s = begin; s < end; ++s) {
    const auto list = candidates.of(s);
    out.candidatePairs += list.size();
    if (!list.empty() && degenerate(slaves[s])) {
      ++out.degenerateSlaves;
    } else if (!list.empty()) {
      for (auto& o : intersectFaces(slaves[s], masters, list, options.polygon)) {
        FaceOverlap r{o.master, o.area, out.points.size(), 0, out.vertices.size(), 0};
        if (options.keepPoints) {
          r.pointCount = o.points.size();
          out.points.insert(out.points.end(), o.points.begin(), o.points.end());
        }
        if (options.keepPolygons) {
          r.vertexCount = o.polygon.size();
          out.vertices.insert(out.vertices.end(), o.polygon.begin(), o.polygon.end());
        }
        out.overlaps.push_back(r);
      }
    }
    out.unpairedSlaves += out.overlaps.size() == out.offsets.back() ? 1 : 0;
    out.offsets.push_back(out.overlaps.size());
  }
}

// Appends `part` (a later chunk) to `all`, shifting its offsets.
void append(FacePairing& all, const FacePairing& part) {
  const std::size_t o0 = all.overlaps.size();
  const std::size_t p0 = all.points.size();
  const std::size_t v0 = all.vertices.size();
  for (std::size_t k = 1; k < part.offsets.size(); ++k) {
    all.offsets.push_back(o0 + part.offsets[k]);
  }
  for (FaceOverlap o : part.overlaps) {
    o.firstPoint += p0;
    o.firstVertex += v0;
    all.overlaps.push_back(o);
  }
  all.points.insert(all.points.end(), part.points.begin(), part.points.end());
  all.vertices.insert(all.vertices.end(), part.vertices.begin(), part.vertices.end());
  all.candidatePairs += part.candidatePairs;
  all.degenerateSlaves += part.degenerateSlaves;
  all.unpairedSlaves += part.unpairedSlaves;
}

} // namespace

double FacePairing::coveredArea(std::size_t slave) const {
  double a = 0;
  for (const auto& o : of(slave)) {
    a += o.area;
  }
  return a;
}

std::size_t FacePairing::bytes() const {
  return offsets.capacity() * sizeof(std::size_t) + overlaps.capacity() * sizeof(FaceOverlap) +
         points.capacity() * sizeof(PolygonPoint) + vertices.capacity() * sizeof(Point3);
}

FacePairing pairFaces(std::span<const Face> slaves, std::span<const Face> masters,
                      const FacePairingOptions& options) {
  checkFaces(slaves, "mortar slave face");
  checkFaces(masters, "mortar master face");
  const SearchMargin none{0.0, 0.0};
  const Candidates candidates =
      findCandidates(boxes(slaves, options.margin), boxes(masters, none), options.exhaustive);
  const std::size_t n = slaves.size();
  // Chunks of at least 2048 faces: below, starting a thread costs more than it saves.
  const std::size_t threads = std::max<std::size_t>(
      1, std::min<std::size_t>(static_cast<std::size_t>(std::max(options.threads, 1)), n / 2048));
  std::vector<FacePairing> parts(threads);
  std::vector<std::thread> workers;
  for (std::size_t t = 1; t < threads; ++t) {
    workers.emplace_back([&, t] {
      pairRange(slaves, masters, candidates, options, n * t / threads, n * (t + 1) / threads, parts[t]);
    });
  }
  pairRange(slaves, masters, candidates, options, 0, n / threads, parts[0]);
  for (auto& w : workers) {
    w.join();
  }
  FacePairing out = std::move(parts[0]);
  for (std::size_t t = 1; t < threads; ++t) {
    append(out, parts[t]);
  }
  return out;
}

std::vector<Face> meshFaces(const Mesh& mesh, std::span<const CellId> cells,
                            const contact::NodePosition& position) {
  std::vector<Face> out;
  out.reserve(cells.size());
  for (const CellId c : cells) {
    Face f{mesh.cellType(c), {}};
    STELLA_ASSERT(isFace(f.type), "mortar face cell");
    for (const NodeId n : mesh.cellNodes(c)) {
      f.nodes.push_back(position(n));
    }
    out.push_back(std::move(f));
  }
  return out;
}

} // namespace stella::mortar
