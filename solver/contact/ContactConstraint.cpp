// The part of the discrete contact constraints shared by every resolution: pairing, geometric
// loop, measured gaps, report, CONT_NOEU.

#include "solver/contact/ContactConstraint.hpp"

#include "messages/Messages.hpp"
#include "solver/contact/ContactAlarm.hpp"
#include "solver/database/Result.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <fmt/format.h>
#include <limits>
#include <mutex>
#include <thread>

namespace stella::contact {

namespace {

// Gap of a link after the displacement increment `du` since its pairing (normal kept fixed).
double linearGap(const ContactLink& l, const std::vector<double>& du) {
  auto at = [&](NodeId n) {
    const auto i = static_cast<std::size_t>(n) * 3;
    return Point3{du[i], du[i + 1], du[i + 2]};
  };
  Point3 rel = at(l.slave);
  for (std::size_t j = 0; j < l.masterNodes.size(); ++j) {
    rel = rel - l.weights[j] * at(l.masterNodes[j]);
  }
  return l.gap + dot(rel, l.normal);
}

} // namespace

ContactConstraint::ContactConstraint(std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs)
    : definition_(std::move(definition)), dofs_(dofs) {
  for (const auto& z : definition_->zones) {
    resolvedZone_.push_back(z.resolve);
    anyResolved_ = anyResolved_ || z.resolve;
    resolvedSlaveNodes_ += z.resolve ? zoneSlaveNodes(*definition_->mesh, z).size() : 0;
  }
  contactEquations_ = contactEquations(*definition_, dofs_);
  uPairing_ = Eigen::VectorXd::Zero(dofs_.physicalCount());
  uStart_ = uPairing_;
}

void ContactConstraint::initialize() {
  pairAt(uStart_);
  states_ = measuredGaps(links_);
}

std::string ContactConstraint::effects() const {
  const auto& s = definition_->settings;
  std::string loop;
  switch (s.geometricUpdate) {
  case GeometricUpdate::Automatic:
    loop = fmt::format("geometric loop AUTOMATIQUE (ITER_GEOM_MAXI={}, RESI_GEOM={})",
                       s.maxGeometricIterations, s.geometricResidual);
    break;
  case GeometricUpdate::Controlled:
    loop = fmt::format("geometric loop CONTROLE (NB_ITER_GEOM={})", s.geometricIterations);
    break;
  case GeometricUpdate::None:
    loop = "no geometric update (REAC_GEOM='SANS': paired once)";
    break;
  }
  if (s.formulation == Formulation::Continue && s.continuous.geometryNewton) {
    loop = fmt::format("geometry in the Newton iterations (ALGO_RESO_GEOM='NEWTON', RESI_GEOM={})",
                       s.geometricResidual);
  }
  std::size_t slaves = 0;
  for (const auto& z : definition_->zones) {
    slaves += zoneSlaveNodes(*definition_->mesh, z).size();
  }
  const char* formulation =
      definition_->settings.formulation == Formulation::Continue ? "CONTINUE" : "DISCRETE";
  return fmt::format("contact {} {}, {} zone(s), {} slave node(s), {}, {}", formulation, resolutionEffects(),
                     definition_->zones.size(), slaves,
                     definition_->hasFriction() ? "Coulomb friction" : "no friction", loop);
}

std::vector<std::string> ContactConstraint::zoneEffects() const {
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < definition_->zones.size(); ++k) {
    const ContactZone& z = definition_->zones[k];
    std::string algorithm = fmt::format("ALGO_CONT='{}'", algorithmName(z.algorithm));
    if (z.algorithm == ContactAlgorithm::Penalty) {
      algorithm += fmt::format(" E_N={:g}", z.normalPenalty);
    }
    std::string friction = "no friction (FROTTEMENT='SANS')";
    if (definition_->hasFriction()) {
      friction =
          fmt::format("Coulomb friction COULOMB={:g}{}", z.coulomb,
                      z.algorithm == ContactAlgorithm::Penalty ? fmt::format(" E_T={:g}", z.tangentPenalty)
                                                               : std::string());
    }
    lines.push_back(fmt::format(
        "zone {}: GROUP_MA_ESCL='{}' on GROUP_MA_MAIT='{}', {}, {}, {} slave node(s){}", k + 1, z.slaveGroup,
        z.masterGroup, z.resolve ? algorithm : std::string("RESOLUTION='NON' (gap measured, no force)"),
        friction, zoneSlaveNodes(*definition_->mesh, z).size(),
        z.pairing == Pairing::Nodal ? ", APPARIEMENT='NODAL'" : ", APPARIEMENT='MAIT_ESCL'"));
  }
  return lines;
}

std::string ContactConstraint::workSummary() const {
  if (pairingThreads_ <= 1) {
    return fmt::format("{} pairing(s)", pairings_);
  }
  return fmt::format("{} pairing(s), {} on {} threads", pairings_,
                     definition_->zones.size() > 1 ? "the zones" : "the slave nodes", pairingThreads_);
}

const std::vector<ContactLink>& ContactConstraint::pairZoneAt(std::size_t z, const NodePosition& position) {
  if (zonePairings_.empty()) {
    PairingOptions options;
    options.dimension = definition_->mesh->dimension();
    options.smoothing = definition_->settings.smoothing;
    // Several zones share the threads (one zone per thread, pairZonesInParallel); one zone
    // splits its slave nodes among them.
    options.threads = definition_->zones.size() > 1 ? 1 : pairingThreads_;
    for (std::size_t k = 0; k < definition_->zones.size(); ++k) {
      zonePairings_.emplace_back(*definition_->mesh, static_cast<int>(k), definition_->zones[k], options);
    }
  }
  return zonePairings_[z].pair(position);
}

void ContactConstraint::pairZonesInParallel(const NodePosition& position) {
  const std::size_t zones = definition_->zones.size();
  pairZoneAt(0, position); // builds every zone's pairing, pairs zone 0
  std::atomic<std::size_t> next{1};
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto work = [&] {
    for (std::size_t z = next++; z < zones; z = next++) {
      try {
        zonePairings_[z].pair(position);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failureMutex);
        failure = failure ? failure : std::current_exception();
      }
    }
  };
  std::vector<std::thread> threads;
  const auto count = std::min<std::size_t>(static_cast<std::size_t>(pairingThreads_), zones - 1);
  for (std::size_t t = 1; t < count; ++t) {
    threads.emplace_back(work);
  }
  work();
  for (auto& t : threads) {
    t.join();
  }
  if (failure) {
    std::rethrow_exception(failure);
  }
}

void ContactConstraint::pairAt(const Eigen::VectorXd& u) {
  const Mesh& mesh = *definition_->mesh;
  const std::vector<double> disp = nodalDisplacement(dofs_, mesh.nodeCount(), u);
  const NodePosition position = meshPositions(mesh, &disp);
  const bool parallelZones = pairingThreads_ > 1 && definition_->zones.size() > 1;
  if (parallelZones) {
    pairZonesInParallel(position);
  }
  std::size_t k = 0;
  for (std::size_t z = 0; z < definition_->zones.size(); ++z) {
    const auto& zoneLinks = parallelZones ? zonePairings_[z].links() : pairZoneAt(z, position);
    links_.resize(std::max(links_.size(), k + zoneLinks.size()));
    std::copy(zoneLinks.begin(), zoneLinks.end(), links_.begin() + static_cast<std::ptrdiff_t>(k));
    k += zoneLinks.size();
  }
  links_.resize(k);
  rows_ = buildLinkRows(links_, dofs_, resolvedZone_, {}, withFrictionRows());
  uPairing_ = u;
  ++pairings_;
  paired();
}

void ContactConstraint::beginStep(const Eigen::VectorXd& u, double time) {
  uStart_ = u;
  time_ = time;
  geometricIterations_ = 1;
  contactIterations_ = 0;
  lastGeometricResidual_.reset();
  alarms_.clear();
  if (definition_->settings.geometricUpdate != GeometricUpdate::None) {
    pairAt(u);
  } else {
    paired(); // the same pairing, a new step start
  }
}

Eigen::VectorXd ContactConstraint::gapsAt(const Eigen::VectorXd& u) const {
  return rows_.problem.gap + rows_.problem.A * (u - uPairing_);
}

double ContactConstraint::geometricResidual(const Eigen::VectorXd& u) const {
  double change = 0.0;
  for (int e : contactEquations_) {
    change = std::max(change, std::abs(u(e) - uPairing_(e)));
  }
  // The step's displacement of the whole structure: contact nodes that hardly move (a body
  // pressed on a fixed one) must not make the criterion a ratio of round-off errors.
  const double step = u.size() > 0 ? (u - uStart_).cwiseAbs().maxCoeff() : 0.0;
  if (step > 0.0) {
    return change / step;
  }
  return change > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
}

double ContactConstraint::geometricCriterion(const Eigen::VectorXd& u) const {
  if (!anyResolved_ || definition_->settings.geometricUpdate == GeometricUpdate::None) {
    return -1.0;
  }
  return geometricResidual(u);
}

bool ContactConstraint::farApart(const Eigen::VectorXd& u) const {
  if (rows_.link.empty() || rows_.link.size() != resolvedSlaveNodes_) {
    return false; // a slave node without a link might find one when paired again
  }
  double change = 0.0;
  for (int e : contactEquations_) {
    change = std::max(change, std::abs(u(e) - uPairing_(e)));
  }
  // A point moved by at most sqrt(3) x the largest component; its gap after a new pairing
  // differs from the linearised one by about that much: a margin of 4.
  return gapsAt(u).minCoeff() > 4.0 * change;
}

bool ContactConstraint::acceptConvergence(const Eigen::VectorXd& u) {
  if (!acceptResolution(u)) {
    return false;
  }
  const auto& s = definition_->settings;
  if (anyResolved_) {
    const double r = geometricResidual(u);
    lastGeometricResidual_ = r;
    if (s.geometricUpdate == GeometricUpdate::Automatic && r > s.geometricResidual && !farApart(u)) {
      if (geometricIterations_ >= s.maxGeometricIterations) {
        throw UserError(msg::make("CONTACT_GEOM_1",
                                  {{"time", time_},
                                   {"geometric_iterations", geometricIterations_},
                                   {"r", r},
                                   {"geometric_residual", s.geometricResidual}},
                                  definition_->location));
      }
      pairAt(u);
      ++geometricIterations_;
      return false;
    }
    if (s.geometricUpdate == GeometricUpdate::Controlled) {
      if (geometricIterations_ < s.geometricIterations) {
        pairAt(u);
        ++geometricIterations_;
        return false;
      }
      if (s.geometricIterations >= 2 && r > 0.01) {
        noteAlarm(alarmLine(
            msg::make("CONTACT_GEOM_2", {{"geometric_iterations", s.geometricIterations}, {"r", r}})));
      }
    }
  }
  finishStep(u);
  return true;
}

void ContactConstraint::finishStep(const Eigen::VectorXd& u) {
  const Mesh& mesh = *definition_->mesh;
  std::vector<LinkState> states = measuredGaps(links_);
  const std::vector<LinkState> rowStates = resolvedStates(u);
  activeLinks_ = 0;
  for (std::size_t i = 0; i < rowStates.size(); ++i) {
    states[static_cast<std::size_t>(rows_.link[i])] = rowStates[i];
    activeLinks_ += rowStates[i].status != LinkStatus::Open ? 1 : 0;
  }
  // Zones only measured (RESOLUTION='NON'): the geometric gap at u (paired again unless
  // REAC_GEOM='SANS', where the gap is linearised on the first pairing).
  const std::vector<double> disp = nodalDisplacement(dofs_, mesh.nodeCount(), u);
  const std::vector<double> change = nodalDisplacement(dofs_, mesh.nodeCount(), u - uPairing_);
  const bool repair = definition_->settings.geometricUpdate != GeometricUpdate::None;
  std::size_t offset = 0;
  for (std::size_t z = 0; z < definition_->zones.size(); ++z) {
    std::size_t count = 0;
    while (offset + count < links_.size() && links_[offset + count].zone == static_cast<int>(z)) {
      ++count;
    }
    if (!resolvedZone_[z]) {
      static const std::vector<ContactLink> none;
      const std::vector<ContactLink>& fresh = repair ? pairZoneAt(z, meshPositions(mesh, &disp)) : none;
      for (std::size_t k = offset; k < offset + count; ++k) {
        if (repair && k - offset < fresh.size()) {
          links_[k] = fresh[k - offset];
          states[k].gap = links_[k].gap;
        } else {
          states[k].gap = linearGap(links_[k], change);
        }
      }
    }
    offset += count;
  }
  maxInterpenetration_ = 0.0;
  NodeId worst = -1;
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (links_[k].paired && -states[k].gap > maxInterpenetration_) {
      maxInterpenetration_ = -states[k].gap;
      worst = links_[k].slave;
    }
  }
  bool measuredPenetration = false;
  for (std::size_t k = 0; k < links_.size(); ++k) {
    measuredPenetration =
        measuredPenetration ||
        (links_[k].paired && !resolvedZone_[static_cast<std::size_t>(links_[k].zone)] && states[k].gap < 0.0);
  }
  if (measuredPenetration) {
    noteAlarm(
        alarmLine(msg::make("CONTACT_8", {{"max_interpenetration", maxInterpenetration_},
                                          {"worst", worst >= 0 ? mesh.nodeName(worst) : std::string("-")}})));
  }
  accepted(rowStates);
  states_ = std::move(states);
  stepAlarms_ = std::move(alarms_);
  alarms_.clear();
}

std::string ContactConstraint::iterationNote() const {
  return fmt::format("CONT {} act. pene {:.2e}", noteActive_, notePenetration_);
}

void ContactConstraint::reportStep(std::ostream& log) const {
  log << fmt::format("   contact: {} geometric iteration(s), {} contact iteration(s)\n", geometricIterations_,
                     contactIterations_);
  log << fmt::format("   Nombre de liaisons de contact : {}\n", activeLinks_);
  log << fmt::format("   interpenetration maximale : {:.6e}\n", maxInterpenetration_);
  for (const std::string& a : stepAlarms_) {
    // "ID: text" -> an alarm of the session (counted in the job diagnostic) when there is a sink
    const std::size_t colon = a.find(": ");
    const bool named = colon != std::string::npos;
    if (!emitAlarm(Diagnostic::alarm(named ? a.substr(0, colon) : std::string("CONTACT"),
                                     named ? a.substr(colon + 2) : a, definition_->location))) {
      log << "   <A> " << a << '\n';
    }
  }
}

void ContactConstraint::store(ResultStep& step) const {
  step.fields["CONT_NOEU"] = std::make_shared<Field>(buildContNoeu(
      static_cast<std::size_t>(definition_->mesh->nodeCount()), links_, states_, definition_->hasFriction()));
}

std::string ContactConstraint::singularNote() const {
  std::vector<std::string> zones;
  for (std::size_t z = 0; z < definition_->zones.size(); ++z) {
    zones.push_back(fmt::format("zone {}: GROUP_MA_ESCL='{}', GROUP_MA_MAIT='{}'", z + 1,
                                definition_->zones[z].slaveGroup, definition_->zones[z].masterGroup));
  }
  return fmt::format(
      "a body may be held only by contact ({}): {} (notice §4.4.2): hold the body with springs of small "
      "stiffness (modelling DIS_T or 2D_DIS_T on POI1 cells made by CREA_MAILLAGE CREA_POI1, stiffness "
      "given by AFFE_CARA_ELEM) or impose DDL_IMPO on one of its points",
      fmt::join(zones, "; "), singularCause());
}

} // namespace stella::contact
