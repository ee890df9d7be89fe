// Structured rectangle and box meshes (see StructuredMesher.hpp). Cells are built on a lattice
// with two steps per division so that mid-edge and centre nodes have integer lattice positions;
// only the lattice points some cell uses become nodes.

#include "solver/mesh/StructuredMesher.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <map>
#include <unordered_map>

namespace stella {

namespace {

using Lattice = std::array<int, 3>;

Lattice average(const std::vector<Lattice>& pts, const std::vector<int>& ids) {
  Lattice s{0, 0, 0};
  for (const int i : ids) {
    for (int d = 0; d < 3; ++d) {
      s[static_cast<std::size_t>(d)] += pts[static_cast<std::size_t>(i)][static_cast<std::size_t>(d)];
    }
  }
  for (auto& v : s) {
    v /= static_cast<int>(ids.size());
  }
  return s;
}

// Every node of a cell from its vertices, following CellTopology's ordering.
std::vector<Lattice> completeNodes(CellType t, std::vector<Lattice> pts) {
  const int nv = vertexCount(t);
  pts.resize(static_cast<std::size_t>(nodeCount(t)));
  for (const auto& e : cellEdges(t)) {
    if (e.mid >= 0) {
      pts[static_cast<std::size_t>(e.mid)] = average(pts, {e.a, e.b});
    }
  }
  for (const auto& f : cellFaces(t)) {
    const int fv = vertexCount(f.type);
    if (static_cast<int>(f.nodes.size()) == 2 * fv + 1) {
      pts[static_cast<std::size_t>(f.nodes.back())] =
          average(pts, std::vector<int>(f.nodes.begin(), f.nodes.begin() + fv));
    }
  }
  if (t == CellType::QUAD9 || t == CellType::HEXA27 || t == CellType::TRIA7) {
    std::vector<int> all(static_cast<std::size_t>(nv));
    for (int i = 0; i < nv; ++i) {
      all[static_cast<std::size_t>(i)] = i;
    }
    pts.back() = average(pts, all);
  }
  return pts;
}

class Builder {
public:
  explicit Builder(const StructuredSpec& s) : spec_(s) {
    for (int d = 0; d < 3; ++d) {
      size_[static_cast<std::size_t>(d)] = 2 * s.divisions[static_cast<std::size_t>(d)] + 1;
    }
  }

  NodeId node(const Lattice& p) {
    const long key = p[0] + size_[0] * (static_cast<long>(p[1]) + size_[1] * static_cast<long>(p[2]));
    const auto it = ids_.find(key);
    if (it != ids_.end()) {
      return it->second;
    }
    pending_.push_back(p);
    const auto id = static_cast<NodeId>(pending_.size() - 1);
    ids_.emplace(key, id);
    return id;
  }

  void cell(CellType t, const std::vector<Lattice>& vertices) {
    auto pts = completeNodes(t, vertices);
    for (const auto& p : pts) {
      node(p);
    }
    cells_.emplace_back(t, std::move(pts));
  }

  Mesh finish(int dim) {
    // Number nodes by lattice order (x fastest) for reproducible, readable numbering.
    std::map<std::array<int, 3>, NodeId> order;
    for (std::size_t i = 0; i < pending_.size(); ++i) {
      order.emplace(Lattice{pending_[i][2], pending_[i][1], pending_[i][0]}, static_cast<NodeId>(i));
    }
    std::vector<NodeId> renum(pending_.size());
    Mesh m;
    m.setDimension(dim);
    for (const auto& [zyx, old] : order) {
      Point3 x{};
      for (int d = 0; d < 3; ++d) {
        const auto k = static_cast<std::size_t>(d);
        const int n = spec_.divisions[k];
        x[k] = d < dim ? spec_.origin[k] +
                             spec_.lengths[k] * pending_[static_cast<std::size_t>(old)][k] / (2.0 * n)
                       : 0.0;
      }
      renum[static_cast<std::size_t>(old)] = m.addNode(x);
    }
    std::vector<CellId> body;
    for (const auto& [t, pts] : cells_) {
      std::vector<NodeId> nodes;
      for (const auto& p : pts) {
        nodes.push_back(renum[static_cast<std::size_t>(node(p))]);
      }
      body.push_back(m.addCell(t, nodes));
    }
    addBoundary(m, body, dim);
    m.setCellGroup(dim == 3 ? "VOLUME" : "SURFACE", body);
    std::vector<NodeId> origin{0};
    m.setNodeGroup("ORIGIN", origin);
    return m;
  }

private:
  // Faces of the body cells lying on a side of the box become boundary cells of that side.
  void addBoundary(Mesh& m, const std::vector<CellId>& body, int dim) {
    static const char* names[3][2] = {{"XMIN", "XMAX"}, {"YMIN", "YMAX"}, {"ZMIN", "ZMAX"}};
    std::map<std::string, std::vector<CellId>> groups;
    for (const CellId c : body) {
      const auto nodes = std::vector<NodeId>(m.cellNodes(c).begin(), m.cellNodes(c).end());
      for (const auto& f : cellFaces(m.cellType(c))) {
        for (int d = 0; d < dim; ++d) {
          const auto k = static_cast<std::size_t>(d);
          for (int side = 0; side < 2; ++side) {
            const double plane = spec_.origin[k] + side * spec_.lengths[k];
            bool on = true;
            for (const int i : f.nodes) {
              on = on && std::abs(m.point(nodes[static_cast<std::size_t>(i)])[k] - plane) <=
                             1e-12 * (1.0 + std::abs(plane) + spec_.lengths[k]);
            }
            if (on) {
              std::vector<NodeId> fn;
              for (const int i : f.nodes) {
                fn.push_back(nodes[static_cast<std::size_t>(i)]);
              }
              groups[names[d][side]].push_back(m.addCell(f.type, fn));
            }
          }
        }
      }
    }
    for (auto& [g, cells] : groups) {
      m.setNodeGroup(g, m.nodesOfCells(cells));
      m.setCellGroup(g, std::move(cells));
    }
  }

  StructuredSpec spec_;
  std::array<int, 3> size_{};
  std::unordered_map<long, NodeId> ids_;
  std::vector<Lattice> pending_;
  std::vector<std::pair<CellType, std::vector<Lattice>>> cells_;
};

[[noreturn]] void refuse(const std::string& what) {
  throw UserError(msg::make("MESHGEN_1", {{"what", what}}));
}

} // namespace

Mesh buildStructuredMesh(const StructuredSpec& spec) {
  const CellType t = spec.type;
  const CellShape shape = shapeOf(t);
  const int dim = dimension(t);
  if (dim < 2 || shape == CellShape::Pyramid || t == CellType::TRIA7) {
    refuse(msg::text("MESHGEN_1.f1", {{"name", std::string(name(t))}}));
  }
  for (int d = 0; d < dim; ++d) {
    const auto k = static_cast<std::size_t>(d);
    if (spec.divisions[k] < 1 || spec.divisions[k] > 100000 || !(spec.lengths[k] > 0.0)) {
      refuse(msg::text("MESHGEN_1.f2"));
    }
  }
  Builder b(spec);
  const int nx = spec.divisions[0];
  const int ny = spec.divisions[1];
  const int nz = dim == 3 ? spec.divisions[2] : 1;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const int x0 = 2 * i, x1 = 2 * i + 2, y0 = 2 * j, y1 = 2 * j + 2, z0 = 2 * k, z1 = 2 * k + 2;
        if (dim == 2) {
          const Lattice v0{x0, y0, 0}, v1{x1, y0, 0}, v2{x1, y1, 0}, v3{x0, y1, 0};
          if (shape == CellShape::Quadrangle) {
            b.cell(t, {v0, v1, v2, v3});
          } else {
            b.cell(t, {v0, v1, v2});
            b.cell(t, {v0, v2, v3});
          }
          continue;
        }
        const std::vector<Lattice> h{{x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0},
                                     {x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}};
        if (shape == CellShape::Hexahedron) {
          b.cell(t, h);
        } else if (shape == CellShape::Pentahedron) {
          b.cell(t, {h[0], h[1], h[2], h[4], h[5], h[6]});
          b.cell(t, {h[0], h[2], h[3], h[4], h[6], h[7]});
        } else {
          // Six tetrahedra around the diagonal 0-6, each positively oriented.
          static const int ring[6] = {1, 2, 3, 7, 4, 5};
          for (int r = 0; r < 6; ++r) {
            const Lattice& a = h[static_cast<std::size_t>(ring[r])];
            const Lattice& c = h[static_cast<std::size_t>(ring[(r + 1) % 6])];
            const Point3 e1{double(a[0] - h[0][0]), double(a[1] - h[0][1]), double(a[2] - h[0][2])};
            const Point3 e2{double(c[0] - h[0][0]), double(c[1] - h[0][1]), double(c[2] - h[0][2])};
            const Point3 e3{double(h[6][0] - h[0][0]), double(h[6][1] - h[0][1]), double(h[6][2] - h[0][2])};
            if (dot(cross(e1, e2), e3) > 0) {
              b.cell(t, {h[0], a, c, h[6]});
            } else {
              b.cell(t, {h[0], c, a, h[6]});
            }
          }
        }
      }
    }
  }
  return b.finish(dim);
}

} // namespace stella
