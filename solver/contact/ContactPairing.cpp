// Pairing of contact zones: exact nearest admissible projection over the master cells through
// the R-tree of their boxes (MasterCellIndex), warm start from the previous pairing, slave-node
// chunks in parallel; normals, tangents and gaps; nodal pairing.

#include "solver/contact/ContactPairing.hpp"

#include "messages/Messages.hpp"
#include "solver/contact/MasterSurface.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

namespace stella::contact {

namespace {

constexpr double unbounded = std::numeric_limits<double>::max();

Point3 normalized(const Point3& v) {
  const double n = norm(v);
  return n > 0.0 ? (1.0 / n) * v : v;
}

// Unit tangents orthogonal to n: the first along the cell's first parametric direction when
// that direction is not parallel to n.
void tangents(const Point3& n, const Point3& d1, int dim, Point3& t1, Point3& t2) {
  if (dim == 1) {
    t1 = Point3{-n[1], n[0], 0.0};
    t2 = Point3{0, 0, 0};
    return;
  }
  Point3 t = d1 - dot(d1, n) * n;
  if (norm(t) < 1e-12 * std::max(norm(d1), 1.0)) {
    const Point3 e = std::abs(n[0]) < 0.9 ? Point3{1, 0, 0} : Point3{0, 1, 0};
    t = e - dot(e, n) * n;
  }
  t1 = normalized(t);
  t2 = cross(n, t1);
}

Point3 chosenVector(VectorChoice choice, const std::array<double, 3>& value, const Point3& geometric,
                    const Point3& d1) {
  if (choice == VectorChoice::Fixed) {
    return normalized(Point3{value[0], value[1], value[2]});
  }
  if (choice == VectorChoice::VectY) {
    const Point3 t = normalized(d1);
    const Point3 y{value[0], value[1], value[2]};
    return normalized(y - dot(y, t) * t);
  }
  return geometric;
}

double smallestAdmissible(const std::vector<Candidate>& candidates) {
  double d = unbounded;
  for (const Candidate& c : candidates) {
    if (c.admissible) {
      d = std::min(d, c.distance);
    }
  }
  return d;
}

} // namespace

struct ZonePairing::Scratch {
  std::vector<int> found;
  std::vector<Candidate> candidates;
  std::vector<std::uint32_t> stamp; // per master cell: the epoch of the last node that tried it
  std::uint32_t epoch = 0;
  long searched = 0;
  int lastCell = -1; // the previous node's cell: the first pairing's start

  void nextNode() {
    if (++epoch == 0) {
      std::fill(stamp.begin(), stamp.end(), 0u);
      epoch = 1;
    }
    candidates.clear();
  }
};

NodePosition meshPositions(const Mesh& mesh, const std::vector<double>* displacement) {
  if (displacement == nullptr || displacement->empty()) {
    return [&mesh](NodeId n) { return mesh.point(n); };
  }
  return [&mesh, displacement](NodeId n) {
    const auto i = static_cast<std::size_t>(n) * 3;
    const Point3 p = mesh.point(n);
    return Point3{p[0] + (*displacement)[i], p[1] + (*displacement)[i + 1], p[2] + (*displacement)[i + 2]};
  };
}

std::array<double, 2> projectOnCell(const Mesh& mesh, const NodePosition& position, CellId cell,
                                    const Point3& x) {
  CellNodes cn;
  cn.type = mesh.cellType(cell);
  const auto nodes = mesh.cellNodes(cell);
  cn.count = static_cast<int>(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    cn.x[i] = position(nodes[i]);
  }
  return projectPoint(cn, info(cn.type).dimension, x);
}

ZonePairing::ZonePairing(const Mesh& mesh, int zoneIndex, const ContactZone& zone,
                         const PairingOptions& options)
    : mesh_(&mesh), zoneIndex_(zoneIndex), zone_(zone), options_(options), dim_(options.dimension - 1) {
  if (zone.projection == Projection::Fixed) {
    throw UserError(msg::make("CONTACT_10", {}, zone.location));
  }
  slaves_ = zoneSlaveNodes(mesh, zone);
  master_ = std::make_unique<MasterSurface>(mesh, zoneMasterCells(mesh, zone), dim_);
  slaveNormalNeeded_ = zone.normal != NormalChoice::Master || zone.pairing == Pairing::Nodal;
  if (slaveNormalNeeded_) {
    const auto* cells = mesh.cellGroup(zone.slaveGroup);
    slave_ = std::make_unique<MasterSurface>(mesh, cells ? *cells : std::vector<CellId>{}, dim_);
    slaveLocal_.reserve(slaves_.size());
    for (NodeId s : slaves_) {
      slaveLocal_.push_back(slave_->local(s));
    }
  }
  links_.resize(slaves_.size());
  previous_.assign(slaves_.size(), -1);
}

ZonePairing::~ZonePairing() = default;
ZonePairing::ZonePairing(ZonePairing&&) noexcept = default;
ZonePairing& ZonePairing::operator=(ZonePairing&&) noexcept = default;

const std::vector<ContactLink>& ZonePairing::pair(const NodePosition& position) {
  const bool indexed = !options_.exhaustive && zone_.pairing != Pairing::Nodal;
  master_->update(position, indexed || zone_.pairing == Pairing::Nodal, 0.0, options_.smoothing);
  if (slave_) {
    slave_->update(position, false, 0.0, true);
  }
  tieTolerance_ = 1e-12 * master_->lengthScale();
  const std::size_t n = slaves_.size();
  // Chunks of at least 4096 nodes: below, starting threads costs more than it saves.
  const std::size_t threads = std::max<std::size_t>(
      1, std::min<std::size_t>(static_cast<std::size_t>(std::max(options_.threads, 1)), n / 4096));
  scratch_.resize(threads);
  for (Scratch& s : scratch_) {
    if (s.stamp.size() != static_cast<std::size_t>(master_->cellCount())) {
      s.stamp.assign(static_cast<std::size_t>(master_->cellCount()), 0u);
      s.epoch = 0;
    }
    s.searched = 0;
  }
  if (threads == 1) {
    pairRange(position, 0, n, scratch_[0]);
  } else {
    std::vector<std::thread> workers;
    workers.reserve(threads - 1);
    for (std::size_t t = 1; t < threads; ++t) {
      workers.emplace_back([this, &position, n, t, threads] {
        pairRange(position, n * t / threads, n * (t + 1) / threads, scratch_[t]);
      });
    }
    pairRange(position, 0, n / threads, scratch_[0]);
    for (auto& w : workers) {
      w.join();
    }
  }
  searched_ = 0;
  for (const Scratch& s : scratch_) {
    searched_ += s.searched;
  }
  first_ = false;
  return links_;
}

void ZonePairing::pairRange(const NodePosition& position, std::size_t begin, std::size_t end,
                            Scratch& scratch) {
  for (std::size_t i = begin; i < end; ++i) {
    pairNode(position, i, scratch);
  }
}

int ZonePairing::findCell(const Point3& x, int previous, Scratch& s) const {
  const MasterSurface& m = *master_;
  s.nextNode();
  CellNodes cn;
  auto tryCell = [&](int c) {
    auto& stamp = s.stamp[static_cast<std::size_t>(c)];
    if (stamp == s.epoch) {
      return;
    }
    stamp = s.epoch;
    m.gather(c, cn);
    s.candidates.push_back(projectionCandidate(cn, c, dim_, x, zone_.extensionTolerance));
  };
  // The cells of the R-tree's cube whose boxes are within `within` of x (Euclidean).
  auto tryAround = [&](double within) {
    m.index().queryAround(x, within, s.found);
    for (int c : s.found) {
      if (squaredDistance(m.box(c), x) <= within * within) {
        tryCell(c);
      }
    }
  };
  auto select = [&] {
    return selectCandidate(s.candidates.data(), s.candidates.data() + s.candidates.size(), tieTolerance_);
  };
  if (options_.exhaustive) {
    for (int c = 0; c < m.cellCount(); ++c) {
      tryCell(c);
    }
    return select();
  }
  // 1. The previous cell (the node's last pairing, or the previous node's cell the first time),
  // 2. its neighbours, 3. growing balls in the R-tree until one holds an admissible projection.
  double d = unbounded;
  double covered = -1.0; // every cell whose box is within this distance was tried
  if (previous >= 0) {
    tryCell(previous);
    d = smallestAdmissible(s.candidates);
    if (d == unbounded) {
      for (int c : m.neighbours(previous)) {
        tryCell(c);
      }
      d = smallestAdmissible(s.candidates);
    }
  }
  if (d == unbounded) {
    ++s.searched;
    double r = m.meanCellSize() > 0.0 ? m.meanCellSize() : 1e-3 * m.lengthScale();
    for (;;) {
      tryAround(r);
      covered = r;
      d = smallestAdmissible(s.candidates);
      if (d < unbounded || s.found.size() == static_cast<std::size_t>(m.cellCount())) {
        break;
      }
      r *= 2.0;
    }
    if (d == unbounded) {
      return -1;
    }
  }
  // The certificate: a cell offering a projection within d (+ ties) has its box within d.
  const double reach = d + tieTolerance_;
  if (reach > covered) {
    tryAround(reach);
  }
  return select();
}

NodeId ZonePairing::findNode(const Point3& x, Scratch& s) const {
  const MasterSurface& m = *master_;
  double best = unbounded;
  int bestLocal = -1;
  auto visit = [&] {
    for (int c : s.found) {
      for (int l : m.cellNodes(c)) {
        const double d = norm(m.position(l) - x);
        if (d < best || (d == best && m.node(l) < m.node(bestLocal))) {
          best = d;
          bestLocal = l;
        }
      }
    }
  };
  double r = m.meanCellSize() > 0.0 ? m.meanCellSize() : 1e-3 * m.lengthScale();
  for (;;) {
    m.index().queryAround(x, r, s.found);
    visit();
    if (bestLocal >= 0) {
      break;
    }
    r *= 2.0;
  }
  if (best > r) {
    m.index().queryAround(x, best, s.found);
    visit();
  }
  return m.node(bestLocal);
}

void ZonePairing::pairNode(const NodePosition& position, std::size_t i, Scratch& scratch) {
  ContactLink& link = links_[i];
  link.zone = zoneIndex_;
  link.slave = slaves_[i];
  link.paired = false;
  link.masterCell = -1;
  link.xi = {0, 0};
  link.masterNodes.clear();
  link.weights.clear();
  link.normal = link.tangent1 = link.tangent2 = link.projection = Point3{0, 0, 0};
  link.gap = 0.0;
  const Point3 x = position(link.slave);
  Point3 slaveNormal{0, 0, 0};
  if (slaveNormalNeeded_) {
    const int l = slaveLocal_[i];
    slaveNormal = l >= 0 ? slave_->nodalNormal(l) : Point3{0, 0, 0};
    slaveNormal = chosenVector(zone_.slaveVector, zone_.slaveVectorValue, slaveNormal,
                               Point3{-slaveNormal[1], slaveNormal[0], 0});
  }
  if (master_->cellCount() == 0) {
    return;
  }
  Point3 masterNormal{0, 0, 0};
  Point3 d1{0, 0, 0};
  if (zone_.pairing == Pairing::Nodal) {
    const NodeId m = findNode(x, scratch);
    link.masterNodes.assign(1, m);
    link.weights.assign(1, 1.0);
    link.projection = master_->position(master_->local(m));
    masterNormal = -1.0 * slaveNormal;
    d1 = Point3{-masterNormal[1], masterNormal[0], 0.0};
    link.paired = true;
  } else {
    const int best = findCell(x, first_ ? scratch.lastCell : previous_[i], scratch);
    scratch.lastCell = best >= 0 ? scratch.candidates[static_cast<std::size_t>(best)].cell : scratch.lastCell;
    if (best < 0) {
      previous_[i] = -1;
      return;
    }
    const Candidate& c = scratch.candidates[static_cast<std::size_t>(best)];
    CellNodes cn;
    master_->gather(c.cell, cn);
    CellPoint g;
    evaluateCell(cn, c.xi, g);
    previous_[i] = c.cell;
    link.masterCell = master_->cell(c.cell);
    link.xi = c.xi;
    const auto nodes = mesh_->cellNodes(link.masterCell);
    link.masterNodes.assign(nodes.begin(), nodes.end());
    link.weights.assign(g.shape.n.begin(), g.shape.n.begin() + cn.count);
    link.projection = g.x;
    d1 = g.d1;
    if (options_.smoothing) {
      const auto locals = master_->cellNodes(c.cell);
      for (std::size_t k = 0; k < locals.size(); ++k) {
        masterNormal = masterNormal + g.shape.n[k] * master_->nodalNormal(locals[k]);
      }
      masterNormal = normalized(masterNormal);
    } else {
      masterNormal = cellNormalAt(g, dim_);
    }
    masterNormal = chosenVector(zone_.masterVector, zone_.masterVectorValue, masterNormal, g.d1);
    link.paired = true;
  }
  Point3 n = masterNormal;
  if (zone_.normal == NormalChoice::Slave) {
    n = -1.0 * slaveNormal;
  } else if (zone_.normal == NormalChoice::MasterSlave) {
    n = normalized(masterNormal - slaveNormal);
  }
  link.normal = n;
  tangents(n, d1, dim_, link.tangent1, link.tangent2);
  link.gap = dot(x - link.projection, n);
  if (zone_.pairingDistance > 0.0 && norm(x - link.projection) > zone_.pairingDistance) {
    link.paired = false;
  }
}

std::vector<ContactLink> pairZone(const Mesh& mesh, const NodePosition& position, int zoneIndex,
                                  const ContactZone& zone, const PairingOptions& options) {
  ZonePairing pairing(mesh, zoneIndex, zone, options);
  pairing.pair(position);
  return pairing.links();
}

std::vector<ContactLink> pairAll(const ContactDefinition& definition, const NodePosition& position) {
  std::vector<ContactLink> all;
  PairingOptions options;
  options.dimension = definition.mesh->dimension();
  options.smoothing = definition.settings.smoothing;
  for (std::size_t z = 0; z < definition.zones.size(); ++z) {
    auto links = pairZone(*definition.mesh, position, static_cast<int>(z), definition.zones[z], options);
    all.insert(all.end(), std::make_move_iterator(links.begin()), std::make_move_iterator(links.end()));
  }
  return all;
}

} // namespace stella::contact
