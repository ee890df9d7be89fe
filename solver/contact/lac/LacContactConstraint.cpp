// LAC (mortar) contact coupled with the Newton iterations of STAT_NON_LINE (see
// LacContactConstraint.hpp).

#include "solver/contact/lac/LacContactConstraint.hpp"

#include "messages/Messages.hpp"
#include "solver/contact/ContactResultField.hpp"
#include "solver/contact/ContactRows.hpp"
#include "solver/contact/mortar/ContElemField.hpp"
#include "solver/database/Result.hpp"
#include "solver/mesh/SkinOrientation.hpp"
#include "solver/nonlinear/SaddleSolver.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <set>

namespace stella::contact::lac {

namespace {

[[noreturn]] void refuseMesh(std::string_view key, msg::Args args, const SourceLocation& at) {
  throw UserError(msg::make(key, args, at));
}

// The node of a patch carrying its LAGS_C: the node shared by the most of its cells, the first in
// the patch's cell order among equals (the centre of a 3D fan, the middle of an edge cut in two, the
// first new node of an edge cut in three); the middle node of a single SEG3, the centre of a
// single QUAD9.
NodeId lagrangeNode(const Mesh& mesh, const Mesh::LacPatch& patch) {
  std::map<NodeId, int> count;
  std::vector<NodeId> order;
  for (CellId c : patch.cells) {
    for (NodeId n : mesh.cellNodes(c)) {
      if (count[n]++ == 0) {
        order.push_back(n);
      }
    }
  }
  NodeId best = order.front();
  for (NodeId n : order) {
    best = count[n] > count[best] ? n : best;
  }
  if (count[best] > 1) {
    return best;
  }
  const auto nodes = mesh.cellNodes(patch.cells.front());
  const CellType type = mesh.cellType(patch.cells.front());
  return type == CellType::SEG3 ? nodes[2] : type == CellType::QUAD9 ? nodes[8] : best;
}

} // namespace

LacContactConstraint::LacContactConstraint(std::shared_ptr<const ContactDefinition> definition,
                                           const DofMap& dofs, fem::Modelling modelling)
    : definition_(std::move(definition)), dofs_(dofs), modelling_(modelling) {
  const Mesh& mesh = *definition_->mesh;
  const auto& patches = mesh.lacPatches();
  patchZone_.assign(patches.size(), -1);
  patchNode_.assign(patches.size(), -1);
  std::set<int> equations;
  for (std::size_t z = 0; z < definition_->zones.size(); ++z) {
    const ContactZone& zone = definition_->zones[z];
    LacZoneCells cells;
    cells.zone = static_cast<int>(z);
    cells.bruteForce = zone.continuous.lacBruteForce;
    cells.currentJacobian = zone.continuous.lacCurrentJacobian;
    cells.smoothing = definition_->settings.smoothing; // LISSAGE (2D; refused in 3D by makeLac)
    cells.masters = zoneMasterCells(mesh, zone);
    std::map<CellId, int> patchOf;
    for (std::size_t p = 0; p < patches.size(); ++p) {
      if (patches[p].zone == zone.slaveGroup) {
        patchZone_[p] = static_cast<int>(z);
        patchNode_[p] = lagrangeNode(mesh, patches[p]);
        for (CellId c : patches[p].cells) {
          patchOf[c] = static_cast<int>(p);
        }
      }
    }
    const auto* slaveCells = mesh.cellGroup(zone.slaveGroup);
    STELLA_ASSERT(slaveCells != nullptr, "LAC slave group checked by DEFI_CONTACT");
    if (patchOf.empty()) {
      refuseMesh("CONTACT_LAC_1", {{"slave_group", zone.slaveGroup}}, zone.location);
    }
    const std::vector<CellId> slaves(slaveCells->begin(), slaveCells->end());
    const auto bounded = boundedVolumes(mesh, slaves, {});
    for (std::size_t i = 0; i < slaves.size(); ++i) {
      const CellId c = slaves[i];
      const CellType t = mesh.cellType(c);
      const bool planar = modelling != fem::Modelling::ThreeD;
      const bool known = planar ? t == CellType::SEG2 || t == CellType::SEG3
                                : t == CellType::TRIA3 || t == CellType::TRIA6 || t == CellType::QUAD4 ||
                                      t == CellType::QUAD8 || t == CellType::QUAD9;
      if (!known) {
        refuseMesh("CONTACT_LAC_1.2",
                   {{"cell_name", mesh.cellName(c)}, {"slave_group", zone.slaveGroup}, {"name", name(t)}},
                   zone.location);
      }
      const auto found = patchOf.find(c);
      if (found == patchOf.end()) {
        refuseMesh("CONTACT_LAC_1.3", {{"cell_name", mesh.cellName(c)}, {"slave_group", zone.slaveGroup}},
                   zone.location);
      }
      if (bounded[i].size() != 1) {
        refuseMesh("CONTACT_LAC_1.4",
                   {{"cell_name", mesh.cellName(c)},
                    {"slave_group", zone.slaveGroup},
                    {"bounded_count", bounded[i].size()}},
                   zone.location);
      }
      cells.slaves.push_back({c, found->second, bounded[i].front().outward ? 1.0 : -1.0});
    }
    for (const auto& group : {cells.masters, slaves}) {
      for (NodeId n : mesh.nodesOfCells(group)) {
        for (int k = 0; k < dofs.components(); ++k) {
          if (dofs.dof(n, k) >= 0) {
            equations.insert(dofs.dof(n, k));
          }
        }
      }
    }
    zones_.push_back(std::move(cells));
  }
  contactEquations_.assign(equations.begin(), equations.end());
  lagsC_.assign(patches.size(), 0.0);
  lagsCStart_ = lagsC_;
  directions_ = modelling == fem::Modelling::ThreeD ? 2 : 1;
  lagsT_.assign(patches.size(), Tangential{0.0, 0.0});
  lagsTStart_ = lagsT_;
  status_.assign(patches.size(), 0);
  accepted_ = status_;
  consistent_ = definition_->settings.continuous.geometryNewton && modelling != fem::Modelling::ThreeD;
  uPairing_ = Eigen::VectorXd::Zero(dofs.physicalCount());
  pairAt(uPairing_);
}

void LacContactConstraint::pairAt(const Eigen::VectorXd& u) {
  const Mesh& mesh = *definition_->mesh;
  LacPairingOptions options;
  options.axisymmetric = modelling_ == fem::Modelling::Axisymmetric;
  options.geometricTangent = consistent_;
  rows_ = pairLacPatches(mesh, zones_, nodalDisplacement(dofs_, mesh.nodeCount(), u), dofs_, options);
  uPairing_ = u.head(dofs_.physicalCount());
  ++pairings_;
  gapRows_.assign(rows_.size(), {});
  for (std::size_t p = 0; consistent_ && p < rows_.size(); ++p) {
    if (paired(p)) {
      gapRows_[p] = exactGapRow(p);
    }
  }
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    if (!paired(p)) {
      lagsC_[p] = 0.0; // not paired: no contact pressure
      lagsT_[p] = Tangential{0.0, 0.0};
    }
  }
}

double LacContactConstraint::gapAt(std::size_t p, const Eigen::VectorXd& u) const {
  const LacPatchRow& r = rows_[p];
  double g = r.integratedGap / r.pairedLength;
  for (const auto& [e, v] : gapRow(p)) {
    g += v * (u(e) - uPairing_(e));
  }
  return g;
}

std::vector<double> LacContactConstraint::meanGaps(const Eigen::VectorXd& u) const {
  std::vector<double> g(rows_.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    if (paired(p)) {
      g[p] = gapAt(p, u);
    }
  }
  return g;
}

std::vector<char> LacContactConstraint::statusAt(const Eigen::VectorXd& u) const {
  std::vector<char> s(rows_.size(), 0);
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    s[p] = paired(p) && lagsC_[p] + rho_ * gapAt(p, u) < 0.0 ? contactCode(p, u) : 0;
  }
  return s;
}

const std::vector<char>& LacContactConstraint::currentStatus(const Eigen::VectorXd& u) {
  if (definition_->settings.continuous.statusLoop == StatusLoop::Newton && !useInitial_) {
    status_ = statusAt(u);
  }
  return status_;
}

void LacContactConstraint::beginStep(const Eigen::VectorXd& u, double time) {
  time_ = time;
  uStart_ = u.head(dofs_.physicalCount());
  lagsC_ = lagsCStart_; // a step cut restarts from the multipliers of its start
  lagsT_ = lagsTStart_;
  limitBefore_.clear();
  limitAfter_.clear();
  const auto& s = definition_->settings;
  if (s.continuous.geometryNewton || s.geometricUpdate != GeometricUpdate::None || !everPaired_) {
    pairAt(uStart_);
  }
  everPaired_ = true;
  statusIterations_ = 0;
  geometricIterations_ = 1;
  eliminations_ = 0;
  useInitial_ = true;
  lastStatus_.clear();
  continuation_.clear();
  status_.assign(rows_.size(), 0);
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    if (!paired(p)) {
      continue;
    }
    if (!firstStep_) {
      status_[p] = accepted_[p];
      continue;
    }
    const ContinuousZone& c = definition_->zones[static_cast<std::size_t>(patchZone_[p])].continuous;
    status_[p] = c.init == ContactInit::Yes               ? 1
                 : c.init == ContactInit::Interpenetrated ? (gapAt(p, uStart_) < 0.0 ? 1 : 0)
                                                          : 0;
  }
}

void LacContactConstraint::addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                                     std::vector<Eigen::Triplet<double>>* tangent) {
  if (definition_->settings.continuous.geometryNewton) {
    pairAt(u); // ALGO_RESO_GEOM='NEWTON': the overlaps and gaps of the current iterate
  }
  const std::vector<char>& status = currentStatus(u);
  int active = 0;
  double penetration = 0.0;
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    if (!paired(p)) {
      continue;
    }
    const LacPatchRow& r = rows_[p];
    const bool on = status[p] != 0;
    const double g = gapAt(p, u);
    if (on) {
      ++active;
      penetration = std::max(penetration, -g);
      const double pressure = lagsC_[p] + rho_ * g;
      for (const auto& [e, v] : r.gradient) {
        forces(e) -= pressure * v;
      }
    }
    if (friction()) {
      addFrictionForces(p, status[p], u, forces, tangent);
    }
    if (tangent != nullptr && consistent_) {
      addGeometricTangent(p, on, on ? lagsC_[p] + rho_ * g : 0.0, *tangent);
    } else if (tangent != nullptr) {
      const double c = on ? rho_ / r.pairedLength : 0.0; // zeros keep the pattern of the pairing
      for (const auto& [i, vi] : r.gradient) {
        for (const auto& [j, vj] : r.gradient) {
          tangent->emplace_back(i, j, c * vi * vj);
        }
      }
    }
  }
  noteActive_ = active;
  notePenetration_ = penetration;
}

void LacContactConstraint::correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                                   SaddleSolver& solver) {
  const std::vector<char> status = currentStatus(u);
  useInitial_ = false;
  lastStatus_ = status;
  // the rows of the Schur complement: the mean gap of each patch in contact, the mean slip of each
  // sticking patch (friction)
  std::vector<SchurRow> rows;
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    if (status[p] == 0) {
      lagsC_[p] = 0.0;
      lagsT_[p] = Tangential{0.0, 0.0};
    } else {
      rows.push_back({p, -1});
    }
  }
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    for (std::size_t a = 0; friction() && status[p] == 1 && a < directions(); ++a) {
      rows.push_back({p, static_cast<int>(a)});
    }
  }
  if (friction()) {
    limitBefore_.resize(rows_.size());
    for (std::size_t p = 0; p < rows_.size(); ++p) {
      limitBefore_[p] = frictionLimit(p);
    }
  }
  std::vector<SlidingNewton> sliding(rows_.size());
  for (std::size_t p = 0; friction() && p < rows_.size(); ++p) {
    sliding[p] = slidingNewton(p, status[p], u); // linearised before the correction
  }
  ++eliminations_;
  if (!rows.empty()) {
    eliminate(u, ddu, dlambda, solver, rows);
  }
  if (friction()) {
    updateSlidingPressures(u, ddu, status, sliding);
    limitAfter_.resize(rows_.size());
    for (std::size_t p = 0; p < rows_.size(); ++p) {
      limitAfter_[p] = frictionLimit(p);
    }
  }
}

void LacContactConstraint::redundant(std::size_t patch, bool slip) const {
  const Mesh& mesh = *definition_->mesh;
  const auto& cells = mesh.lacPatches()[patch].cells;
  const int zone = patchZone_[patch];
  throw UserError(msg::make("CONTACT_11.4",
                            {{"time", time_},
                             {"slip", slip ? "slip" : "gap"},
                             {"cell_name", mesh.cellName(cells.front())},
                             {"zone", zone + 1}},
                            definition_->zones[static_cast<std::size_t>(zone)].location));
}

bool LacContactConstraint::statusSettled(const Eigen::VectorXd& u) {
  const auto& c = definition_->settings.continuous;
  const bool newton = c.statusLoop == StatusLoop::Newton;
  const std::vector<char> now = statusAt(u);
  const std::vector<char>& used = newton && !lastStatus_.empty() ? lastStatus_ : status_;
  int changed = 0;
  for (std::size_t p = 0; p < now.size(); ++p) {
    changed += now[p] != used[p] ? 1 : 0;
  }
  if (changed == 0) {
    return true;
  }
  status_ = now;
  lastStatus_ = now;
  ++statusIterations_;
  int patches = 0;
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    patches += paired(p) ? 1 : 0;
  }
  const int cap = newton                ? 2 * patches + 10
                  : c.iterationsPerNode ? c.statusIterationFactor * patches
                                        : c.maxStatusIterations;
  if (statusIterations_ > cap) {
    throw UserError(msg::make("CONTACT_26.3", {{"time", time_}, {"cap", cap}, {"changed", changed}},
                              definition_->location));
  }
  continuation_ = fmt::format("contact status changed on {} LAC patch(es): Newton iterations go on", changed);
  return false;
}

double LacContactConstraint::geometricResidual(const Eigen::VectorXd& u) const {
  double moved = 0.0;
  for (int e : contactEquations_) {
    moved = std::max(moved, std::fabs(u(e) - uPairing_(e)));
  }
  const double step = (u.head(uStart_.size()) - uStart_).cwiseAbs().maxCoeff();
  return step > 0.0 ? moved / step : 0.0;
}

bool LacContactConstraint::geometrySettled(const Eigen::VectorXd& u) {
  const auto& s = definition_->settings;
  bool again = false;
  if (s.continuous.geometryNewton || s.geometricUpdate == GeometricUpdate::Automatic) {
    again = geometricResidual(u) > s.geometricResidual;
    if (again && !s.continuous.geometryNewton && geometricIterations_ >= s.maxGeometricIterations) {
      throw UserError(msg::make("CONTACT_GEOM_1.2",
                                {{"time", time_},
                                 {"max_geometric_iterations", s.maxGeometricIterations},
                                 {"geometric_residual", geometricResidual(u)},
                                 {"geometric_residual_2", s.geometricResidual}},
                                definition_->location));
    }
  } else if (s.geometricUpdate == GeometricUpdate::Controlled) {
    again = geometricIterations_ < s.geometricIterations;
  }
  if (!again) {
    return true;
  }
  pairAt(u);
  ++geometricIterations_;
  continuation_ = "geometric update: LAC mortar pairing recomputed";
  return false;
}

bool LacContactConstraint::acceptConvergence(const Eigen::VectorXd& u) {
  continuation_.clear();
  if (!statusSettled(u) || !frictionSettled() || !geometrySettled(u)) {
    return false;
  }
  accepted_ = statusAt(u);
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    if (accepted_[p] == 0) {
      lagsC_[p] = 0.0;
      lagsT_[p] = Tangential{0.0, 0.0};
    }
  }
  lagsCStart_ = lagsC_;
  lagsTStart_ = lagsT_;
  firstStep_ = false;
  stepGaps_ = meanGaps(u);
  return true;
}

std::string LacContactConstraint::effects() const {
  const auto& s = definition_->settings;
  const char* geometry =
      s.continuous.geometryNewton                        ? "NEWTON"
      : s.geometricUpdate == GeometricUpdate::Automatic  ? "POINT_FIXE (REAC_GEOM='AUTOMATIQUE')"
      : s.geometricUpdate == GeometricUpdate::Controlled ? "POINT_FIXE (REAC_GEOM='CONTROLE')"
                                                         : "POINT_FIXE (REAC_GEOM='SANS')";
  return fmt::format(
      "contact CONTINUE LAC (mortar, one LAGS_C per patch), ALGO_RESO_GEOM={}, ALGO_RESO_CONT={}", geometry,
      s.continuous.statusLoop == StatusLoop::Newton ? "NEWTON" : "POINT_FIXE");
}

std::vector<std::string> LacContactConstraint::zoneEffects() const {
  std::vector<std::string> out;
  for (const auto& z : zones_) {
    const ContactZone& zone = definition_->zones[static_cast<std::size_t>(z.zone)];
    int patches = 0;
    for (int pz : patchZone_) {
      patches += pz == z.zone ? 1 : 0;
    }
    out.push_back(
        fmt::format("zone {}: master '{}', slave '{}', ALGO_CONT='LAC', {} patches, {} slave cells, "
                    "{} master cells, TYPE_APPA='{}', TYPE_JACOBIEN='{}'",
                    z.zone + 1, zone.masterGroup, zone.slaveGroup, patches, z.slaves.size(), z.masters.size(),
                    z.bruteForce ? "ROBUSTE" : "RAPIDE", z.currentJacobian ? "ACTUALISE" : "INITIAL"));
  }
  return out;
}

std::string LacContactConstraint::workSummary() const {
  return fmt::format("{} mortar pairing(s)", pairings_);
}

std::string LacContactConstraint::iterationNote() const {
  return fmt::format("LAC {} act. pene {:.2e}", noteActive_, notePenetration_);
}

void LacContactConstraint::reportStep(std::ostream& log) const {
  int active = 0;
  for (char c : accepted_) {
    active += c != 0 ? 1 : 0;
  }
  log << fmt::format("   geometric iterations (mortar pairings): {}\n", geometricIterations_);
  log << fmt::format("   contact iteration(s): {}\n", eliminations_);
  log << fmt::format("   Nombre de patchs LAC en contact : {}\n", active);
}

void LacContactConstraint::store(ResultStep& step) const {
  const Mesh& mesh = *definition_->mesh;
  std::vector<mortar::LacPatchState> states(rows_.size());
  for (std::size_t p = 0; p < rows_.size(); ++p) {
    if (patchZone_[p] < 0) {
      continue;
    }
    auto& s = states[p];
    s.pressure = lagsC_[p];
    s.contact = accepted_[p] != 0;
    if (paired(p)) {
      s.gap = p < stepGaps_.size() ? stepGaps_[p] : rows_[p].integratedGap / rows_[p].pairedLength;
      s.coefficient = rows_[p].pairedLength / rows_[p].length;
    }
  }
  step.fields["CONT_ELEM"] = std::make_shared<Field>(mortar::buildContElem(mesh, states));
  const auto [out, c0] = multiplierDepl(step, !friction() ? 0 : directions() == 2 ? 2 : 1);
  if (out == nullptr) {
    return;
  }
  for (std::size_t p = 0; p < patchNode_.size(); ++p) {
    if (patchNode_[p] >= 0) {
      const auto n = static_cast<std::size_t>(patchNode_[p]);
      out->value(n, c0) = lagsC_[p];
      out->setDefined(n, c0);
    }
  }
  if (friction()) {
    storeFriction(*out, c0 + 1);
  }
  step.fields["DEPL"] = out;
}

std::string LacContactConstraint::singularNote() const {
  return "with ALGO_CONT='LAC' a body held only by contact is held once its patches are in contact (the "
         "augmented term of the patches in contact stiffens it): CONTACT_INIT='OUI' puts every paired patch "
         "in "
         "contact at the first iteration; otherwise impose DDL_IMPO on one of its points (notice §4.4.2)";
}

} // namespace stella::contact::lac
