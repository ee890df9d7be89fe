// Continuous contact at integration points (ContinuousPointContact.hpp): which zones need them,
// the points of the slave cells (the INTEGRATION rule, its weights times the Jacobian) and their
// pairing on the master cells of their cell's nodes.

#include "solver/contact/ContinuousPointContact.hpp"

#include "messages/Messages.hpp"
#include "solver/contact/CellProjection.hpp"
#include "solver/contact/ContinuousIntegrationRule.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <set>

namespace stella::contact {

namespace {} // namespace

std::vector<std::pair<int, double>>
rowAlong(const DofMap& dofs, const std::vector<std::pair<NodeId, double>>& terms, const Point3& v) {
  std::vector<std::pair<int, double>> row;
  for (int c = 0; c < dofs.components(); ++c) {
    const double vc = v[static_cast<std::size_t>(c)];
    for (const auto& [node, a] : terms) {
      const int e = dofs.dof(node, c);
      if (e >= 0 && vc != 0.0) {
        row.emplace_back(e, a * vc);
      }
    }
  }
  return row;
}

namespace {

bool nodalAuto(CellType type) {
  return !contactIntegrationDefined(type) ||
         contactIntegrationRule(type, ContactIntegration::Auto, 0).atNodes();
}

} // namespace

bool needsContactPoints(const ContactDefinition& definition) {
  for (const auto& zone : definition.zones) {
    if (!zone.resolve) {
      continue;
    }
    if (zone.continuous.integration != ContactIntegration::Auto) {
      return true;
    }
    const auto* cells = definition.mesh->cellGroup(zone.slaveGroup);
    if (cells == nullptr) {
      continue;
    }
    for (CellId c : *cells) {
      if (!nodalAuto(definition.mesh->cellType(c))) {
        return true;
      }
    }
  }
  return false;
}

ContinuousPointContactConstraint::ContinuousPointContactConstraint(
    std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs, fem::Modelling modelling)
    : ContactConstraint(std::move(definition), dofs), modelling_(modelling) {}

void ContinuousPointContactConstraint::buildPoints() {
  const Mesh& mesh = *definition_->mesh;
  const NodePosition position = meshPositions(mesh, nullptr); // weights on the initial configuration
  multiplierOfNode_.assign(static_cast<std::size_t>(mesh.nodeCount()), -1);
  for (const auto& l : links_) {
    if (resolvedZone_[static_cast<std::size_t>(l.zone)] &&
        multiplierOfNode_[static_cast<std::size_t>(l.slave)] < 0) {
      multiplierOfNode_[static_cast<std::size_t>(l.slave)] = static_cast<int>(multiplierNode_.size());
      multiplierNode_.push_back(l.slave);
    }
  }
  for (std::size_t z = 0; z < definition_->zones.size(); ++z) {
    const ContactZone& zone = definition_->zones[z];
    const auto* cells = mesh.cellGroup(zone.slaveGroup);
    if (cells == nullptr || !zone.resolve) {
      continue;
    }
    for (CellId c : *cells) {
      const CellType type = mesh.cellType(c);
      const auto rule =
          contactIntegrationRule(type, zone.continuous.integration, zone.continuous.integrationOrder);
      const fem::ReferenceElement& ref = fem::referenceElement(type);
      const auto nodes = mesh.cellNodes(c);
      std::vector<Point3> x;
      for (NodeId n : nodes) {
        x.push_back(position(n));
      }
      for (int g = 0; g < rule.size(); ++g) {
        const Eigen::Vector3d& xi = rule.points[static_cast<std::size_t>(g)];
        const Eigen::VectorXd n = ref.values(xi);
        ContactPoint p;
        p.zone = static_cast<int>(z);
        p.cell = c;
        p.penalised = zone.algorithm == ContactAlgorithm::ContinuePenalty;
        p.rho = p.penalised ? zone.continuous.penalty : zone.continuous.augmentation;
        p.weight = rule.weights[static_cast<std::size_t>(g)] * skinCellJacobian(ref, x, xi);
        double r = 0.0;
        for (std::size_t k = 0; k < nodes.size(); ++k) {
          p.nodes.push_back(nodes[k]);
          p.shape.push_back(n(static_cast<Eigen::Index>(k)));
          p.multiplier.push_back(multiplierOfNode_[static_cast<std::size_t>(nodes[k])]);
          r += n(static_cast<Eigen::Index>(k)) * x[k][0];
        }
        if (modelling_ == fem::Modelling::Axisymmetric) {
          p.weight *= r; // per radian, like the volume integrals
        }
        points_.push_back(std::move(p));
      }
    }
  }
  checkPointCount();
  markExcludedPoints();
  penalisedNode_.assign(multiplierNode_.size(), 0);
  for (const ContactPoint& p : points_) {
    for (int i : p.multiplier) {
      if (i >= 0 && p.penalised) {
        penalisedNode_[static_cast<std::size_t>(i)] = 1;
      }
    }
  }
  penaltyFactor_.assign(definition_->zones.size(), 1.0);
  lambda_.assign(multiplierNode_.size(), 0.0);
  lambdaT_.assign(multiplierNode_.size(), Eigen::Vector2d::Zero());
  lambdaTStart_ = lambdaT_;
  pressureT_.assign(points_.size(), Eigen::Vector2d::Zero());
  closed_.assign(points_.size(), 0);
  pressureTStart_ = pressureT_;
  lambdaStart_ = lambda_;
  status_.assign(points_.size(), 0);
  contactStart_ = status_;
}

// Fewer contact points than multipliers in a zone (GAUSS ORDRE_INT=1 on SEG2 or QUAD4 cells, 2 on
// SEG3) leave a combination of LAGS_C without equation (zero at every point): refused.
void ContinuousPointContactConstraint::checkPointCount() const {
  for (std::size_t z = 0; z < definition_->zones.size(); ++z) {
    std::set<int> multipliers;
    long count = 0;
    for (const ContactPoint& p : points_) {
      if (p.zone == static_cast<int>(z) && !p.penalised) { // penalised: no multiplier unknowns
        ++count;
        multipliers.insert(p.multiplier.begin(), p.multiplier.end());
      }
    }
    multipliers.erase(-1);
    if (count > 0 && count < static_cast<long>(multipliers.size())) {
      const ContinuousZone& c = definition_->zones[z].continuous;
      throw UserError(
          msg::make("CONTACT_INTEG_1",
                    {{"integration_name", integrationName(c.integration)},
                     {"integration_order",
                      c.integrationOrder > 0 ? fmt::format(" ORDRE_INT={}", c.integrationOrder) : ""},
                     {"count", count},
                     {"z", z + 1},
                     {"multipliers_count", multipliers.size()}},
                    c.integrationAt));
    }
  }
}

// Each point projected on the master cells its slave nodes are paired with (the admissible one
// nearest to it), with the master's normal there, oriented as the nodes' links.
void ContinuousPointContactConstraint::pairPoints() {
  const Mesh& mesh = *definition_->mesh;
  const std::vector<double> disp = nodalDisplacement(dofs_, mesh.nodeCount(), uPairing_);
  const NodePosition position = meshPositions(mesh, &disp);
  std::vector<std::vector<int>> linksOfNode(static_cast<std::size_t>(mesh.nodeCount()));
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (links_[k].paired && links_[k].masterCell >= 0) {
      linksOfNode[static_cast<std::size_t>(links_[k].slave)].push_back(static_cast<int>(k));
    }
  }
  const int dim = mesh.dimension(); // the master cells' parametric dimension is dim - 1
  for (ContactPoint& p : points_) {
    const ContactZone& zone = definition_->zones[static_cast<std::size_t>(p.zone)];
    p.paired = false;
    p.row.clear();
    p.frictionRow = {};
    Point3 x{0, 0, 0};
    Point3 reference{0, 0, 0};
    std::set<CellId> candidates;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      x = x + p.shape[k] * position(p.nodes[k]);
      for (int l : linksOfNode[static_cast<std::size_t>(p.nodes[k])]) {
        const ContactLink& link = links_[static_cast<std::size_t>(l)];
        if (link.zone == p.zone) {
          candidates.insert(link.masterCell);
          reference = reference + link.normal;
        }
      }
    }
    Candidate best;
    CellNodes bestCell;
    for (CellId c : candidates) {
      CellNodes cell;
      cell.type = mesh.cellType(c);
      const auto nodes = mesh.cellNodes(c);
      cell.count = static_cast<int>(nodes.size());
      for (std::size_t j = 0; j < nodes.size(); ++j) {
        cell.x[j] = position(nodes[j]);
      }
      Candidate cand = projectionCandidate(cell, static_cast<int>(c), dim - 1, x, zone.extensionTolerance);
      if (cand.admissible && cand.distance < best.distance) {
        best = cand;
        bestCell = cell;
      }
    }
    if (best.cell < 0 || (zone.pairingDistance >= 0.0 && best.distance > zone.pairingDistance)) {
      continue;
    }
    CellPoint cp;
    evaluateCell(bestCell, best.xi, cp);
    Point3 n = dim == 3 ? cross(cp.d1, cp.d2) : Point3{cp.d1[1], -cp.d1[0], 0.0};
    n = (1.0 / norm(n)) * n;
    if (dot(n, reference) < 0.0) {
      n = -1.0 * n;
    }
    p.paired = true;
    p.gap = dot(n, x - cp.x);
    const auto masterNodes = mesh.cellNodes(static_cast<CellId>(best.cell));
    // the gap's gradient A_p along n: +N_k n on the slave nodes, -phi_j n on the master nodes
    std::vector<std::pair<NodeId, double>> terms;
    for (std::size_t k = 0; k < p.nodes.size(); ++k) {
      if (p.shape[k] != 0.0) {
        terms.emplace_back(p.nodes[k], p.shape[k]);
      }
    }
    for (std::size_t j = 0; j < masterNodes.size(); ++j) {
      if (cp.shape.n[j] != 0.0) {
        terms.emplace_back(masterNodes[j], -cp.shape.n[j]);
      }
    }
    p.row = rowAlong(dofs_, terms, n);
    if (friction()) {
      pairFriction(p, n, terms);
    }
  }
}

void ContinuousPointContactConstraint::paired() {
  if (points_.empty() && multiplierNode_.empty()) {
    buildPoints(); // once: the links are the slave nodes
  }
  pairPoints();
}

} // namespace stella::contact
