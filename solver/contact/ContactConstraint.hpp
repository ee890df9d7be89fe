#pragma once
// What every discrete contact constraint of STAT_NON_LINE shares (DEFI_CONTACT
// FORMULATION='DISCRETE'): the pairing on the current positions (mesh + u) and its rows on the
// equations, the geometric loop (REAC_GEOM AUTOMATIQUE / CONTROLE / SANS, notice §2.4), the
// gaps of the zones that are only measured (RESOLUTION='NON', §4.8), the per-step report, the
// CONT_NOEU field and the advice for a body held only by contact (§4.4.2). The resolution
// itself (dual CONTRAINTE/GCP, penalty) is the derived class's: it provides the forces, the
// correction and the state of the resolved links.

#include "solver/contact/ContactResultField.hpp"
#include "solver/contact/ContactRows.hpp"
#include "solver/nonlinear/StepConstraint.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stella {
class DofMap;
}

namespace stella::contact {

class ContactConstraint : public StepConstraint {
public:
  ContactConstraint(std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs);
  // The first pairing, on the initial configuration (called once after construction).
  void initialize();
  // Threads of the pairing (P ncpus): the zones share them, one zone at a time per thread; a
  // single zone splits its slave nodes among them. Before initialize().
  void setPairingThreads(int threads) { pairingThreads_ = threads; }

  std::string effects() const override;
  std::vector<std::string> zoneEffects() const override;
  std::string workSummary() const override;
  void beginStep(const Eigen::VectorXd& u, double time) override;
  bool acceptConvergence(const Eigen::VectorXd& u) override;
  std::string iterationNote() const override;
  void reportStep(std::ostream& log) const override;
  void store(ResultStep& step) const override;
  std::string singularNote() const override;

  // For tests and the report.
  const std::vector<ContactLink>& links() const { return links_; }
  const std::vector<LinkState>& states() const { return states_; }
  int geometricIterations() const { return geometricIterations_; }
  int contactIterations() const { return contactIterations_; }
  int activeLinks() const { return activeLinks_; }
  double maxInterpenetration() const { return maxInterpenetration_; }
  int pairings() const { return pairings_; }

protected:
  // The resolution's name for effects() (e.g. "CONTRAINTE").
  virtual std::string resolutionEffects() const = 0;
  // Called after each pairing (rows_ rebuilt): keep per-link data consistent.
  virtual void paired() {}
  // The states of the resolved rows at the converged displacement `u` (one per row of rows_).
  virtual std::vector<LinkState> resolvedStates(const Eigen::VectorXd& u) const = 0;
  // Last chance to refuse a converged state (ADAPT_COEF_PENA); true accepts.
  virtual bool acceptResolution(const Eigen::VectorXd& u) {
    (void)u;
    return true;
  }
  // The step was accepted with these states (friction history, GLISSIERE links that closed).
  virtual void accepted(const std::vector<LinkState>& rowStates) { (void)rowStates; }
  virtual bool withFrictionRows() const { return false; }
  // Why the stiffness must be invertible without the contact conditions (singularNote()).
  virtual std::string singularCause() const {
    return "the discrete formulation solves the mechanical problem without the contact conditions first, "
           "so the stiffness must be invertible without them";
  }

  // Gaps of the resolved rows at u, linearised on the current pairing.
  Eigen::VectorXd gapsAt(const Eigen::VectorXd& u) const;
  void addContactIterations(int n) { contactIterations_ += n; }
  // A line for the step's report (alarms of the resolution).
  void noteAlarm(std::string text) const { alarms_.push_back(std::move(text)); }

  std::shared_ptr<const ContactDefinition> definition_;
  const DofMap& dofs_;
  std::vector<bool> resolvedZone_;
  std::vector<ContactLink> links_;
  LinkRows rows_;
  Eigen::VectorXd uPairing_; // displacement of the current pairing
  Eigen::VectorXd uStart_;   // displacement at the start of the step
  double time_ = 0.0;
  int noteActive_ = 0;           // for the convergence table
  double notePenetration_ = 0.0; // idem
  // The geometric criterion at u (what REAC_GEOM='AUTOMATIQUE' compares with RESI_GEOM and CONTROLE
  // with 1 %) for the convergence table; negative when nothing is resolved or REAC_GEOM='SANS'.
  double geometricCriterion(const Eigen::VectorXd& u) const;
  // Pairs every zone again at u (ALGO_RESO_GEOM='NEWTON': the geometry of the current iterate).
  void pairAgain(const Eigen::VectorXd& u) { pairAt(u); }

private:
  void pairAt(const Eigen::VectorXd& u);
  // Pairs zone z at the positions (its ZonePairing, warm after the first call).
  const std::vector<ContactLink>& pairZoneAt(std::size_t z, const NodePosition& position);
  // Every zone paired at the positions, zones shared among pairingThreads_ threads (P ncpus).
  void pairZonesInParallel(const NodePosition& position);
  // Criterion of the geometric loop: max |u - u_pairing| on the contact nodes over the step's
  // displacement max |u - u_start| (all DOFs).
  double geometricResidual(const Eigen::VectorXd& u) const;
  void measure(const Eigen::VectorXd& u, std::vector<LinkState>& states) const;
  void finishStep(const Eigen::VectorXd& u);

  std::vector<int> contactEquations_;
  std::size_t resolvedSlaveNodes_ = 0; // slave nodes of the zones with RESOLUTION='OUI'
  // Every slave node of the resolved zones has a link and every gap at `u` exceeds the motion of
  // the contact nodes since the pairing by a margin: pairing again cannot close a link, so the
  // geometric loop (REAC_GEOM='AUTOMATIQUE') stops there: a zone far from contact costs one
  // pairing per step, not a second Newton pass.
  bool farApart(const Eigen::VectorXd& u) const;
  std::vector<ZonePairing> zonePairings_; // one per zone, kept across the geometric loop
  int pairingThreads_ = 1;
  std::vector<LinkState> states_;
  int geometricIterations_ = 0;
  int contactIterations_ = 0;
  int activeLinks_ = 0;
  double maxInterpenetration_ = 0.0;
  int pairings_ = 0;
  std::optional<double> lastGeometricResidual_;
  bool anyResolved_ = false;
  mutable std::vector<std::string> alarms_; // reported with the step, then cleared
  mutable std::vector<std::string> stepAlarms_;
};

} // namespace stella::contact
