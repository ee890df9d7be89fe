// Continuous (LAGS_C, LAGS_F1) contact coupled with the Newton iterations of STAT_NON_LINE; the
// friction part is in ContinuousContactFriction.cpp.

#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/ContactResultField.hpp"
#include "solver/contact/ContinuousIntegrationRule.hpp"
#include "solver/contact/MultiplierSchur.hpp"

#include "messages/Messages.hpp"
#include "solver/contact/ContactAlarm.hpp"
#include "solver/database/Result.hpp"
#include "solver/fem/Quadrature.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/nonlinear/SaddleSolver.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella::contact {

namespace {

// The slave cell types whose INTEGRATION='AUTO' points are their nodes (code_aster's scheme,
// ContinuousIntegrationRule): SEG2, SEG3, TRIA3, QUAD4, QUAD9; TRIA6 and QUAD8 have points that
// are not nodes.
bool nodeIntegrable(CellType type) {
  return contactIntegrationDefined(type) &&
         contactIntegrationRule(type, ContactIntegration::Auto, 0).atNodes();
}

} // namespace

ContinuousContactConstraint::ContinuousContactConstraint(std::shared_ptr<const ContactDefinition> definition,
                                                         const DofMap& dofs, fem::Modelling modelling)
    : ContactConstraint(std::move(definition), dofs), modelling_(modelling) {}

std::string ContinuousContactConstraint::resolutionEffects() const {
  std::vector<std::string> zones;
  for (const auto& z : definition_->zones) {
    if (z.resolve) {
      zones.push_back(z.algorithm == ContactAlgorithm::ContinuePenalty
                          ? fmt::format("PENALISATION COEF_PENA_CONT={}", z.continuous.penalty)
                          : fmt::format("STANDARD COEF_CONT={}", z.continuous.augmentation));
    }
  }
  const auto& c = definition_->settings.continuous;
  return fmt::format("{} (LAGS_C on the slave nodes, INTEGRATION='AUTO'), ALGO_RESO_CONT={}{}{}",
                     fmt::join(zones, "; "), c.statusLoop == StatusLoop::Newton ? "NEWTON" : "POINT_FIXE",
                     c.geometryNewton ? ", ALGO_RESO_GEOM=NEWTON (pairing and geometric tangent in the "
                                        "Newton iterations)"
                                      : "",
                     penetrationEffects());
}

void ContinuousContactConstraint::computeWeights() {
  const Mesh& mesh = *definition_->mesh;
  // On the initial configuration: the contact forces of small strains (DEFORMATION='PETIT', the
  // only one of stella) balance stresses measured on it, so the patch test holds exactly.
  const NodePosition position = meshPositions(mesh, nullptr);
  std::vector<double> nodeWeight(static_cast<std::size_t>(mesh.nodeCount()), 0.0);
  for (const auto& zone : definition_->zones) {
    const auto* cells = mesh.cellGroup(zone.slaveGroup);
    if (cells == nullptr || !zone.resolve) {
      continue;
    }
    for (CellId c : *cells) {
      const CellType type = mesh.cellType(c);
      if (!nodeIntegrable(type)) {
        throw UserError(msg::make(
            "CONTACT_20.2",
            {{"name", name(type)}, {"cell_name", mesh.cellName(c)}, {"slave_group", zone.slaveGroup}},
            zone.location));
      }
      const fem::ReferenceElement& ref = fem::referenceElement(type);
      const fem::QuadratureRule& rule = fem::rigiRule(type, fem::IntegrationRole::Skin);
      const auto nodes = mesh.cellNodes(c);
      std::vector<Point3> x;
      for (NodeId n : nodes) {
        x.push_back(position(n));
      }
      // w_i = integral of N_i (x r in AXIS) over the cell, with the skin rule of the pressures:
      // the consistent nodal forces of a uniform pressure, so that the patch test holds.
      for (int g = 0; g < rule.size(); ++g) {
        const Eigen::Vector3d& xi = rule.points[static_cast<std::size_t>(g)];
        const Eigen::VectorXd n = ref.values(xi);
        double scale = rule.weights[static_cast<std::size_t>(g)] * skinCellJacobian(ref, x, xi);
        if (modelling_ == fem::Modelling::Axisymmetric) {
          double r = 0.0;
          for (std::size_t k = 0; k < nodes.size(); ++k) {
            r += n(static_cast<Eigen::Index>(k)) * x[k][0];
          }
          scale *= r; // per radian, like the volume integrals
        }
        for (std::size_t k = 0; k < nodes.size(); ++k) {
          nodeWeight[static_cast<std::size_t>(nodes[k])] += n(static_cast<Eigen::Index>(k)) * scale;
        }
      }
    }
  }
  weightLink_.assign(links_.size(), 0.0);
  for (std::size_t k = 0; k < links_.size(); ++k) {
    weightLink_[k] = nodeWeight[static_cast<std::size_t>(links_[k].slave)];
  }
}

void ContinuousContactConstraint::paired() {
  lagsC_.resize(links_.size(), 0.0);
  lagsCStart_.resize(links_.size(), 0.0);
  contactLink_.resize(links_.size(), 0);
  status_.resize(links_.size(), 0);
  lagsF_.resize(links_.size(), Eigen::Vector2d::Zero());
  lagsFStart_.resize(links_.size(), Eigen::Vector2d::Zero());
  threshold_.resize(links_.size(), 0.0);
  if (weightLink_.size() != links_.size()) {
    computeWeights(); // once: on the initial configuration, and links are the slave nodes
  }
  std::vector<char> hasRow(links_.size(), 0);
  for (int k : rows_.link) {
    hasRow[static_cast<std::size_t>(k)] = 1;
  }
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (hasRow[k] == 0) {
      lagsC_[k] = 0.0; // not paired (or not resolved): no contact pressure
      lagsF_[k].setZero();
    }
  }
  frictionPaired();
  const auto m = static_cast<Eigen::Index>(rows_.link.size());
  weight_.resize(m);
  coefficient_.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    const ContactZone& z = definition_->zones[static_cast<std::size_t>(links_[k].zone)];
    weight_(i) = weightLink_[k];
    coefficient_(i) = z.algorithm == ContactAlgorithm::ContinuePenalty
                          ? z.continuous.penalty * penaltyFactor(links_[k].zone)
                          : z.continuous.augmentation;
  }
}

bool ContinuousContactConstraint::cycleTreatment(int zone) const {
  const std::string& a = definition_->zones[static_cast<std::size_t>(zone)].continuous.adaptation;
  return a == "CYCLAGE" || a == "TOUT";
}

bool ContinuousContactConstraint::penalised(Eigen::Index row) const {
  const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)]);
  return definition_->zones[static_cast<std::size_t>(links_[k].zone)].algorithm ==
         ContactAlgorithm::ContinuePenalty;
}

std::vector<char> ContinuousContactConstraint::statusAt(const Eigen::VectorXd& u) const {
  std::vector<char> s(links_.size(), 0);
  const Eigen::VectorXd g = gapsAt(u);
  const Eigen::MatrixXd slip = friction() ? slipsAt(u) : Eigen::MatrixXd();
  for (Eigen::Index i = 0; i < g.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    if (k < frozen_.size() && frozen_[k] >= 0) {
      s[k] = static_cast<char>(frozen_[k]); // a cycling node (ADAPTATION='CYCLAGE')
    } else {
      // a node of zero weight (on the axis of an AXIS model) carries no contact force
      const double indicator = penalised(i) ? g(i) : lagsC_[k] + coefficient_(i) * g(i);
      s[k] = (indicator < 0.0 || heldClosed(k)) && weight_(i) > 0.0 ? 1 : 0;
    }
    if (s[k] != 0 && friction()) {
      s[k] = frictionStatus(i, slip.row(i).transpose());
    }
  }
  return s;
}

const std::vector<char>& ContinuousContactConstraint::currentStatus(const Eigen::VectorXd& u) {
  if (definition_->settings.continuous.statusLoop == StatusLoop::Newton && !useInitial_) {
    status_ = statusAt(u);
  }
  return status_;
}

void ContinuousContactConstraint::beginStep(const Eigen::VectorXd& u, double time) {
  lagsC_ = lagsCStart_; // a step cut restarts from the multipliers of its start
  lagsF_ = lagsFStart_;
  ContactConstraint::beginStep(u, time);
  resetFrictionStep();
  statusIterations_ = 0;
  changes_.assign(links_.size(), 0);
  frozen_.assign(links_.size(), -1);
  continuation_.clear();
  useInitial_ = true;
  lastStatus_.clear();
  noteGeometry_ = 0.0; // paired at u: nothing moved yet (ALGO_RESO_GEOM='NEWTON')
  const Eigen::VectorXd g = gapsAt(u);
  status_.assign(links_.size(), 0);
  for (Eigen::Index i = 0; i < g.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    if (!firstStep_) {
      status_[k] = contactLink_[k];
      continue;
    }
    const ContinuousZone& c = definition_->zones[static_cast<std::size_t>(links_[k].zone)].continuous;
    if (weight_(i) <= 0.0) {
      continue;
    }
    switch (c.init) {
    case ContactInit::Yes:
      status_[k] = 1;
      break;
    case ContactInit::Interpenetrated:
      status_[k] = g(i) < 0.0 && (c.initDistance < 0.0 || -g(i) <= c.initDistance) ? 1 : 0;
      break;
    case ContactInit::No:
      status_[k] = 0;
      break;
    }
  }
  applyInitialThreshold(); // SEUIL_INIT, GLISSIERE
}

void ContinuousContactConstraint::addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                                            std::vector<Eigen::Triplet<double>>* tangent) {
  pairInNewton(u);
  const Eigen::Index m = rows_.problem.A.rows();
  if (m == 0) {
    return;
  }
  const std::vector<char>& status = currentStatus(u);
  const Eigen::VectorXd g = gapsAt(u);
  const SparseRows& a = rows_.problem.A;
  const Eigen::MatrixXd slip = friction() ? slipsAt(u) : Eigen::MatrixXd();
  const bool geometric = tangent != nullptr && geometryNewton();
  std::vector<double> displacement;
  if (geometric) {
    displacement = nodalDisplacement(dofs_, definition_->mesh->nodeCount(), u);
  }
  const NodePosition position = meshPositions(*definition_->mesh, geometric ? &displacement : nullptr);
  int active = 0;
  double penetration = 0.0;
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    const bool on = status[k] != 0;
    const double rho = coefficient_(i);
    const double w = weight_(i);
    if (on) {
      ++active;
      penetration = std::max(penetration, -g(i));
      // -w (lambda + rho g) grad g (PENALISATION: lambda = rho g, eliminated)
      const double pressure = penalised(i) ? rho * g(i) : lagsC_[k] + rho * g(i);
      for (SparseRows::InnerIterator it(a, i); it; ++it) {
        forces(it.col()) -= w * pressure * it.value();
      }
    }
    if (tangent != nullptr) {
      const double c = on ? rho * w : 0.0; // zeros keep the pattern of the pairing
      for (SparseRows::InnerIterator p(a, i); p; ++p) {
        for (SparseRows::InnerIterator q(a, i); q; ++q) {
          tangent->emplace_back(static_cast<int>(p.col()), static_cast<int>(q.col()),
                                c * p.value() * q.value());
        }
      }
    }
    if (geometric) { // w (lambda + rho g) d2g: the variation of the normal and of the projection
      const double pressure = !on ? 0.0 : penalised(i) ? rho * g(i) : lagsC_[k] + rho * g(i);
      addGeometricTangent(i, w * pressure, position, *tangent);
    }
    if (friction()) {
      addFrictionForces(i, status[k], slip.row(i).transpose(), forces, tangent,
                        geometric ? &position : nullptr, u);
    }
  }
  noteActive_ = active;
  notePenetration_ = penetration;
}

void ContinuousContactConstraint::correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu,
                                          Eigen::VectorXd& dlambda, SaddleSolver& solver) {
  const Eigen::Index m = rows_.problem.A.rows();
  const std::vector<char> status = currentStatus(u);
  useInitial_ = false;
  if (m == 0) {
    return;
  }
  lastStatus_ = status;
  if (!friction() && definition_->settings.continuous.statusLoop == StatusLoop::Newton) {
    correctWithLinearisedStatus(u, status, ddu, dlambda, solver);
    return;
  }
  recordThreshold();
  linearisedSlipRowsAt(u); // ALGO_RESO_GEOM='NEWTON': the slip's variation with the geometry
  const std::vector<SlidingNewton> sliding = slidingLinearisations(u, status);
  // The multipliers solving the Schur complement: the normal ones of the augmented-Lagrangian rows
  // in contact and (ALGO_FROT='STANDARD') the tangential ones of the sticking rows. Each has its
  // constraint row B (A, or T_j: the gap, or the slip along friction direction j, vanishes) and its
  // force column C (the derivative of the forces with respect to it): C = B except for the normal
  // multiplier of a node sliding with ALGO_RESO_FROT='NEWTON', whose friction force follows it
  // (A - mu sum_j e_j T_j, e = q / |q| the sliding direction), and for the tangential multipliers with
  // ALGO_RESO_GEOM='NEWTON', whose slip varies with the geometry too (B = T_j + G_j, slipRow).
  struct Multiplier {
    Eigen::Index row;
    int tangent;                      // -1: normal; else the friction direction
    Eigen::Vector2d frictionCoupling; // the coefficients of T_j in C (normal multipliers)
  };
  const Eigen::MatrixXd slip = friction() ? slipsAt(u) : Eigen::MatrixXd();
  const bool newtonFriction = friction() && !definition_->settings.continuous.frictionFixedPoint;
  std::vector<Multiplier> contact;
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    if (penalised(i)) {
      continue;
    }
    if (status[k] == 0) {
      lagsC_[k] = 0.0; // -(w / rho) lambda = 0
      lagsF_[k].setZero();
      continue;
    }
    Eigen::Vector2d coupling = Eigen::Vector2d::Zero();
    if (newtonFriction && status[k] >= 2 && lagsC_[k] < 0.0) {
      coupling = -coulombOfRow(i) * slidingDirection(i, status[k], slip.row(i).transpose());
    }
    contact.push_back({i, -1, coupling});
    if (friction() && status[k] == 1 && !zoneOfRow(i).frictionPenalised) {
      for (int j = 0; j < frictionDirections(i); ++j) {
        contact.push_back({i, j, Eigen::Vector2d::Zero()});
      }
    }
  }
  addContactIterations(1);
  if (contact.empty()) {
    updateSlidingPressures(u, ddu, status, sliding);
    return;
  }
  const SparseRows& a = rows_.problem.A;
  const auto constraintRow = [&](const Multiplier& c) -> const SparseRows& {
    return c.tangent < 0 ? a : slipRow(c.tangent);
  };
  // Adds factor x C_j into the dense vector v (the force column of multiplier j).
  const auto addColumn = [&](const Multiplier& c, double factor, auto&& v) {
    for (SparseRows::InnerIterator it(c.tangent < 0 ? a : frictionRow(c.tangent), c.row); it; ++it) {
      v(it.col()) += factor * it.value();
    }
    for (int j = 0; j < 2; ++j) {
      if (c.frictionCoupling(j) != 0.0) {
        for (SparseRows::InnerIterator it(frictionRow(j), c.row); it; ++it) {
          v(it.col()) += factor * c.frictionCoupling(j) * it.value();
        }
      }
    }
  };
  bool symmetricSchur = !geometricFriction();
  for (const auto& c : contact) {
    symmetricSchur = symmetricSchur && c.frictionCoupling.isZero(0.0);
  }
  const auto mc = static_cast<Eigen::Index>(contact.size());
  const Eigen::Index n = ddu.size();
  const Eigen::MatrixXd s = schurByColumnBlocks(
      mc, n, solver,
      [&](Eigen::Index j, Eigen::Ref<Eigen::VectorXd> x) {
        addColumn(contact[static_cast<std::size_t>(j)], 1.0, x);
      },
      [&](Eigen::Index i, const Eigen::MatrixXd& x,
          Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>> out) {
        const Multiplier& c = contact[static_cast<std::size_t>(i)];
        for (SparseRows::InnerIterator it(constraintRow(c), c.row); it; ++it) {
          out += it.value() * x.row(it.col());
        }
      });
  const Eigen::VectorXd g = gapsAt(u);
  Eigen::VectorXd rhs(mc);
  for (Eigen::Index i = 0; i < mc; ++i) {
    const Multiplier& c = contact[static_cast<std::size_t>(i)];
    double bdu = 0.0;
    for (SparseRows::InnerIterator it(constraintRow(c), c.row); it; ++it) {
      bdu += it.value() * ddu(it.col());
    }
    rhs(i) = (c.tangent >= 0 ? slip(c.row, c.tangent) : g(c.row)) + bdu;
  }
  // w dlambda; non-symmetric with ALGO_RESO_FROT='NEWTON' and sliding nodes
  const Eigen::VectorXd y = solveMultiplierSchur(
      s, rhs, symmetricSchur, [&](Eigen::Index i) { redundant(contact[static_cast<std::size_t>(i)].row); });
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  for (Eigen::Index j = 0; j < mc; ++j) {
    const Multiplier& c = contact[static_cast<std::size_t>(j)];
    addColumn(c, y(j), f);
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(c.row)]);
    (c.tangent >= 0 ? lagsF_[k](c.tangent) : lagsC_[k]) += y(j) / weight_(c.row);
  }
  applyMultiplierForces(f, ddu, dlambda, solver);
  updateSlidingPressures(u, ddu, status, sliding); // the sliding multipliers' Newton update
}

void ContinuousContactConstraint::redundant(Eigen::Index row) const {
  const auto& l = links_[static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(row)])];
  throw UserError(msg::make("CONTACT_11",
                            {{"time", time_},
                             {"friction", friction() ? " or slip" : ""},
                             {"node_name", definition_->mesh->nodeName(l.slave)},
                             {"zone", l.zone + 1}},
                            definition_->zones[static_cast<std::size_t>(l.zone)].location));
}

bool ContinuousContactConstraint::acceptResolution(const Eigen::VectorXd& u) {
  continuation_.clear();
  const auto& c = definition_->settings.continuous;
  if (!geometryConverged()) {
    return false; // ALGO_RESO_GEOM='NEWTON': RESI_GEOM not met yet
  }
  const std::vector<char> now = statusAt(u);
  const bool newton = c.statusLoop == StatusLoop::Newton;
  const std::vector<char>& used = newton ? lastStatus_ : status_;
  if (rows_.link.empty() || now == used || (newton && lastStatus_.empty() && now == status_)) {
    return (!friction() || acceptFriction(u)) && acceptPenetration(u);
  }
  int changed = 0;
  int frozen = 0;
  for (std::size_t k = 0; k < now.size(); ++k) {
    if (k >= used.size() || now[k] == used[k]) {
      continue;
    }
    ++changed;
    // ADAPTATION='CYCLAGE': a node that went in and out of contact twice in the step (flip-flop)
    // keeps the status its multiplier asks for (in contact while compressed) for the rest of it.
    if (++changes_[k] >= 4 && cycleTreatment(links_[k].zone)) {
      frozen_[k] = lagsC_[k] < 0.0 ? 1 : 0;
      ++frozen;
    }
  }
  if (frozen > 0) {
    noteAlarm(alarmLine(msg::make("CONTACT_27", {{"frozen", frozen}, {"time", time_}})));
  }
  status_ = statusAt(u); // with the frozen nodes
  ++statusIterations_;
  const int cap = newton                ? 2 * static_cast<int>(rows_.link.size()) + 10
                  : c.iterationsPerNode ? c.statusIterationFactor * static_cast<int>(rows_.link.size())
                                        : c.maxStatusIterations;
  if (statusIterations_ > cap) {
    throw UserError(
        msg::make("CONTACT_26", {{"time", time_}, {"cap", cap}, {"changed", changed}}, definition_->location)
            .withNote(newton ? msg::text("CONTACT_26.n1") : msg::text("CONTACT_26.n2")));
  }
  lastStatus_ = status_;
  continuation_ = fmt::format("contact status changed on {} slave node(s): Newton iterations go on", changed);
  return false;
}

std::string ContinuousContactConstraint::continuationNote() const {
  return continuation_.empty() ? ContactConstraint::continuationNote() : continuation_;
}

std::vector<LinkState> ContinuousContactConstraint::resolvedStates(const Eigen::VectorXd& u) const {
  const Eigen::VectorXd g = gapsAt(u);
  const std::vector<char> status = statusAt(u);
  const Eigen::MatrixXd slip = friction() ? slipsAt(u) : Eigen::MatrixXd();
  std::vector<LinkState> states(rows_.link.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    const double lambda = status[k] == 0 ? 0.0 : penalised(row) ? coefficient_(row) * g(row) : lagsC_[k];
    states[i].gap = g(row);
    states[i].normalForce = -weight_(row) * lambda;
    states[i].status = status[k] != 0 ? LinkStatus::Sliding : LinkStatus::Open;
    if (friction() && status[k] != 0) {
      frictionState(row, status[k], slip.row(row).transpose(), states[i]);
    }
  }
  return states;
}

void ContinuousContactConstraint::accepted(const std::vector<LinkState>& rowStates) {
  for (std::size_t i = 0; i < rowStates.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    const double w = weight_(static_cast<Eigen::Index>(i));
    lagsC_[k] = w > 0.0 ? -rowStates[i].normalForce / w : 0.0;
    contactLink_[k] = rowStates[i].status != LinkStatus::Open ? 1 : 0;
    closed_[k] = closed_[k] != 0 || (contactLink_[k] != 0 &&
                                     definition_->zones[static_cast<std::size_t>(links_[k].zone)].slide)
                     ? 1
                     : 0; // GLISSIERE: held closed from now on
    if (friction()) {
      acceptFrictionState(static_cast<Eigen::Index>(i), rowStates[i]);
      // the next step starts sliding (in the same sense along a single friction direction), or
      // sticking
      const bool backwards = slidingSenseInStatus(static_cast<Eigen::Index>(i)) && lagsF_[k](0) < 0.0;
      contactLink_[k] = rowStates[i].status == LinkStatus::Sliding ? (backwards ? 3 : 2) : contactLink_[k];
    }
  }
  lagsCStart_ = lagsC_;
  lagsFStart_ = lagsF_;
  firstStep_ = false;
}

void ContinuousContactConstraint::store(ResultStep& step) const {
  ContactConstraint::store(step);
  const std::size_t directions = !friction() ? 0 : rows_.friction.T2.rows() > 0 ? 2 : 1;
  const auto [out, c0] = multiplierDepl(step, directions);
  if (out == nullptr) {
    return;
  }
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (!resolvedZone_[static_cast<std::size_t>(links_[k].zone)]) {
      continue;
    }
    const auto n = static_cast<std::size_t>(links_[k].slave);
    out->value(n, c0) = k < lagsC_.size() ? lagsC_[k] : 0.0;
    out->setDefined(n, c0);
  }
  if (friction()) {
    storeFriction(*out, c0 + 1); // LAGS_F1, LAGS_F2
  }
  step.fields["DEPL"] = out;
}

std::string ContinuousContactConstraint::singularNote() const {
  return "with FORMULATION='CONTINUE' a body held only by contact is held once its contact nodes are in "
         "contact (the augmented term COEF_CONT x w x grad g grad g of the nodes in contact stiffens it): "
         "CONTACT_INIT='OUI' puts every slave node in contact at the first iteration; otherwise impose "
         "DDL_IMPO on one of its points or hold it with springs of small stiffness (notice §4.4.2)";
}

} // namespace stella::contact
