#pragma once
// Dual discrete contact in STAT_NON_LINE (ALGO_CONT='CONTRAINTE' or 'GCP', notice §3.2.1): after
// each linear solve of Newton, the correction is projected on the admissible set by solving
// the contact problem condensed on the links with the factorised stiffness (the "contact
// discret" box of the notice's Figure 3.1.2-1). The multipliers mu (normal nodal forces,
// compressive positive) are total values: the next residual includes A^T mu.
// GLISSIERE='OUI': a link that is closed at its pairing or has carried a force becomes
// bilateral (multiplier of any sign) for the rest of the analysis.

#include "solver/contact/ContactConstraint.hpp"
#include "solver/contact/DiscreteContact.hpp"

namespace stella::contact {

class DualContactConstraint : public ContactConstraint {
public:
  DualContactConstraint(std::shared_ptr<const ContactDefinition> definition, const DofMap& dofs,
                        ContactAlgorithm algorithm);

  void addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                 std::vector<Eigen::Triplet<double>>* tangent) override;
  bool symmetric() const override { return true; }
  void correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
               SaddleSolver& solver) override;

  // Normal force of each link of the pairing (0 for links not resolved).
  const std::vector<double>& linkForces() const { return muLink_; }
  int solves() const { return solves_; }

protected:
  std::string resolutionEffects() const override;
  void paired() override;
  std::vector<LinkState> resolvedStates(const Eigen::VectorXd& u) const override;
  void accepted(const std::vector<LinkState>& rowStates) override;

private:
  DualResult solve(const ContactProblem& problem, StiffnessInverse& k, const Eigen::VectorXd& du0,
                   const DualStart& start) const;

  ContactAlgorithm algorithm_;
  DualOptions options_;
  Eigen::VectorXd mu_;          // per row of the current pairing
  std::vector<double> muLink_;  // per link (kept across pairings)
  std::vector<char> bilateral_; // per link: GLISSIERE link closed once
  double closedTolerance_ = 0.0;
  int solves_ = 0;
};

} // namespace stella::contact
