// The interpenetration control of the penalised continuous contact (ALGO_CONT='PENALISATION'):
// PENE_MAXI of ADAPTATION='ADAPT_COEF'/'TOUT' (notice §4.12: the penalty is raised while the
// interpenetration exceeds it; default 1e-2 x the shortest edge of the zone, ContinuousAdaptation)
// and DEFI_LIST_INST ECHEC EVENEMENT='INTERPENETRATION' (ACTION='ADAPT_COEF_PENA': COEF_PENA_CONT
// raised, at most COEF_MAXI; 'ARRET': the analysis stops). Both act once Newton has converged: the
// penalty of the zone is multiplied by 10, as the discrete formulation does with E_N, and the
// Newton iterations go on with it; the factor is kept for the next steps. The nodal
// (ContinuousContactConstraint) and point (ContinuousPointContactConstraint) formulations share
// raisePenalties(); each measures its own interpenetration (nodes or contact points).

#include "messages/Messages.hpp"
#include "solver/contact/ContactAlarm.hpp"
#include "solver/contact/ContinuousAdaptation.hpp"
#include "solver/contact/ContinuousContactConstraint.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace stella::contact {

namespace {

constexpr double raise = 10.0;

} // namespace

std::string penetrationEffects(const ContactDefinition& definition,
                               const std::optional<FailurePolicy>& policy) {
  std::string s;
  for (std::size_t z = 0; z < definition.zones.size(); ++z) {
    const ContactZone& zone = definition.zones[z];
    if (zone.resolve && adaptsCoefficients(zone.continuous)) {
      s += fmt::format(", zone {}: ADAPTATION='{}' coefficients x E*/h = {:.6g}", z + 1,
                       zone.continuous.adaptation, zone.continuous.stiffness);
      if (zone.algorithm == ContactAlgorithm::ContinuePenalty && zone.continuous.maxPenetration) {
        s += fmt::format(", penalty raised above PENE_MAXI = {:.6g}", *zone.continuous.maxPenetration);
      }
    }
  }
  if (policy) {
    s += policy->action == FailurePolicy::Action::AdaptPenalty
             ? fmt::format(", COEF_PENA_CONT adapted above PENE_MAXI={} (COEF_MAXI={})",
                           policy->maxPenetration, policy->maxCoefficient)
             : fmt::format(", stop above PENE_MAXI={}", policy->maxPenetration);
  }
  return s;
}

std::vector<std::string> raisePenalties(const ContactDefinition& definition,
                                        const std::optional<FailurePolicy>& policy,
                                        const std::vector<double>& penetration, double time,
                                        std::vector<double>& factor,
                                        const std::function<void(std::string)>& alarm) {
  const auto& zones = definition.zones;
  factor.resize(zones.size(), 1.0);
  std::vector<std::string> raised;
  for (std::size_t z = 0; z < zones.size(); ++z) {
    const ContactZone& zone = zones[z];
    if (!zone.resolve || zone.algorithm != ContactAlgorithm::ContinuePenalty) {
      continue;
    }
    const double pene = z < penetration.size() ? penetration[z] : 0.0;
    const double penalty = zone.continuous.penalty * factor[z];
    bool raise10 = adaptsCoefficients(zone.continuous) && zone.continuous.maxPenetration &&
                   pene > *zone.continuous.maxPenetration;
    double limit = std::numeric_limits<double>::infinity();
    if (policy && pene > policy->maxPenetration) {
      if (policy->action == FailurePolicy::Action::Stop) {
        throw UserError(msg::make(
            "CONTACT_14",
            {{"pene", pene}, {"max_penetration", policy->maxPenetration}, {"time", time}, {"z", z + 1}},
            definition.location));
      }
      raise10 = true;
      limit = policy->maxCoefficient;
    }
    if (!raise10) {
      continue;
    }
    const double next = std::min(raise * penalty, std::max(penalty, limit));
    if (next <= penalty) {
      alarm(alarmLine(msg::make("CONTACT_15.2", {{"pene", pene},
                                                 {"max_penetration", policy->maxPenetration},
                                                 {"z", z + 1},
                                                 {"max_coefficient", policy->maxCoefficient}})));
      continue;
    }
    factor[z] = next / zone.continuous.penalty;
    raised.push_back(fmt::format("zone {}: interpenetration {:.3e}, COEF_PENA_CONT {:.6g} -> {:.6g}", z + 1,
                                 pene, penalty, next));
  }
  if (!raised.empty() && policy) {
    alarm(alarmLine(msg::make(
        "CONTACT_16.2",
        {{"max_penetration", policy->maxPenetration}, {"time", time}, {"join", fmt::join(raised, "; ")}})));
  }
  return raised;
}

double ContinuousContactConstraint::penaltyFactor(int zone) const {
  const auto z = static_cast<std::size_t>(zone);
  return z < penaltyFactor_.size() ? penaltyFactor_[z] : 1.0;
}

std::string ContinuousContactConstraint::penetrationEffects() const {
  return contact::penetrationEffects(*definition_, policy_);
}

bool ContinuousContactConstraint::acceptPenetration(const Eigen::VectorXd& u) {
  const auto& zones = definition_->zones;
  penaltyFactor_.resize(zones.size(), 1.0);
  const Eigen::Index m = rows_.problem.A.rows();
  if (m == 0) {
    return true;
  }
  // the largest interpenetration of the penalised nodes of each zone (a node of zero weight
  // carries no force)
  const Eigen::VectorXd g = gapsAt(u);
  std::vector<double> penetration(zones.size(), 0.0);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    if (penalised(i) && weight_(i) > 0.0) {
      auto& p = penetration[static_cast<std::size_t>(links_[k].zone)];
      p = std::max(p, -g(i));
    }
  }
  const std::vector<std::string> raised =
      raisePenalties(*definition_, policy_, penetration, time_, penaltyFactor_,
                     [this](std::string text) { noteAlarm(std::move(text)); });
  if (raised.empty()) {
    return true;
  }
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    if (penalised(i)) {
      const ContactZone& zone = zones[static_cast<std::size_t>(links_[k].zone)];
      coefficient_(i) = zone.continuous.penalty * penaltyFactor(links_[k].zone);
    }
  }
  continuation_ = fmt::format("penalty raised ({}): Newton iterations go on", fmt::join(raised, "; "));
  return false;
}

} // namespace stella::contact
