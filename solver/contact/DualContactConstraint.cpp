// Dual discrete contact (CONTRAINTE, GCP) coupled with the Newton iterations of STAT_NON_LINE.

#include "solver/contact/DualContactConstraint.hpp"

#include "messages/Messages.hpp"
#include "solver/contact/SaddleStiffness.hpp"

#include <cmath>
#include <fmt/format.h>

namespace stella::contact {

namespace {

double meshSize(const Mesh& mesh) {
  double size = 0.0;
  for (NodeId n = 0; n < mesh.nodeCount(); ++n) {
    for (double x : mesh.point(n)) {
      size = std::max(size, std::abs(x));
    }
  }
  return size > 0.0 ? size : 1.0;
}

} // namespace

DualContactConstraint::DualContactConstraint(std::shared_ptr<const ContactDefinition> definition,
                                             const DofMap& dofs, ContactAlgorithm algorithm)
    : ContactConstraint(std::move(definition), dofs), algorithm_(algorithm) {
  const auto& s = definition_->settings;
  options_.rightHandSidesPerSolve = s.rightHandSidesPerSolve;
  options_.iterationFactor = s.contactIterationFactor;
  options_.stopIfSingular = s.stopIfSingular;
  options_.computeDisplacement = false; // correct() applies the multipliers with one solve
  if (algorithm_ == ContactAlgorithm::Gcp) {
    options_.tolerance = s.gcpTolerance.value_or(0.0);
    options_.maxIterations = s.gcpMaxIterations;
    options_.admissibleLineSearch = s.lineSearch == LineSearch::Admissible;
    options_.dirichletPreconditioner = s.dirichletPreconditioner;
    options_.preconditionerResidual = s.preconditionerResidual;
    options_.preconditionerIterations = s.preconditionerMaxIterations;
  }
  closedTolerance_ = 1e-10 * meshSize(*definition_->mesh);
}

std::string DualContactConstraint::resolutionEffects() const {
  const auto& s = definition_->settings;
  if (algorithm_ == ContactAlgorithm::Gcp) {
    return fmt::format("GCP (projected conjugate gradient, RESI_ABSO={}, RECH_LINEAIRE={}, PRE_COND={})",
                       options_.tolerance, options_.admissibleLineSearch ? "ADMISSIBLE" : "NON_ADMISSIBLE",
                       options_.dirichletPreconditioner ? "DIRICHLET" : "SANS");
  }
  return fmt::format("CONTRAINTE (active set on the Schur complement, NB_RESOL={}, ITER_CONT_MULT={})",
                     s.rightHandSidesPerSolve, s.contactIterationFactor);
}

void DualContactConstraint::paired() {
  muLink_.resize(links_.size(), 0.0);
  bilateral_.resize(links_.size(), 0);
  const auto m = static_cast<Eigen::Index>(rows_.link.size());
  mu_ = Eigen::VectorXd::Zero(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    const ContactLink& l = links_[k];
    if (definition_->zones[static_cast<std::size_t>(l.zone)].slide &&
        (bilateral_[k] != 0 || l.gap <= closedTolerance_)) {
      bilateral_[k] = 1;
      rows_.problem.bilateral[static_cast<std::size_t>(i)] = true;
    }
    mu_(i) = muLink_[k];
  }
}

void DualContactConstraint::addForces(const Eigen::VectorXd& u, Eigen::VectorXd& forces,
                                      std::vector<Eigen::Triplet<double>>* tangent) {
  (void)u;
  (void)tangent; // dual methods add nothing to the stiffness
  if (mu_.size() > 0) {
    forces += rows_.problem.A.transpose() * mu_;
  }
}

DualResult DualContactConstraint::solve(const ContactProblem& problem, StiffnessInverse& k,
                                        const Eigen::VectorXd& du0, const DualStart& start) const {
  const Mesh& mesh = *definition_->mesh;
  try {
    return algorithm_ == ContactAlgorithm::Gcp ? solveProjectedGradient(problem, k, du0, options_, &start)
                                               : solveActiveSet(problem, k, du0, options_, &start);
  } catch (const SingularContactError& e) {
    const auto& l = links_[static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(e.link())])];
    throw UserError(msg::make("CONTACT_11.3",
                              {{"time", time_}, {"node_name", mesh.nodeName(l.slave)}, {"zone", l.zone + 1}},
                              definition_->zones[static_cast<std::size_t>(l.zone)].location));
  } catch (const ContactNotConverged& e) {
    throw UserError(msg::make("CONTACT_12",
                              {{"algorithm_name", algorithmName(algorithm_)},
                               {"time", time_},
                               {"iterations", e.result.iterations},
                               {"max_interpenetration", e.result.maxInterpenetration}},
                              definition_->location)
                        .withNote(algorithm_ == ContactAlgorithm::Gcp ? msg::text("CONTACT_12.n1")
                                                                      : msg::text("CONTACT_12.n2")));
  }
}

void DualContactConstraint::correct(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                                    SaddleSolver& solver) {
  const Eigen::Index m = rows_.problem.A.rows();
  if (m == 0) {
    return;
  }
  SaddleStiffness k(solver, dlambda.size(), ddu.size());
  const SparseRows& a = rows_.problem.A;
  // The free correction: the linear solve included the forces A^T mu of the current multipliers.
  // They are the algorithms' starting point (GCP starts from them, CONTRAINTE from their links).
  DualStart start;
  if (mu_.cwiseAbs().maxCoeff() > 0.0) {
    Eigen::VectorXd y;
    k.solveWithMultipliers(a.transpose() * mu_, start.w, y);
    ddu -= start.w;
    if (y.size() == dlambda.size()) {
      dlambda -= y;
    }
    start.lambda = mu_;
  }
  ContactProblem problem{a, gapsAt(u), rows_.problem.bilateral};
  const DualResult r = solve(problem, k, ddu, start);
  // One solve applies the multipliers: ddu (free) + K^-1 A^T lambda.
  if (r.lambda.cwiseAbs().maxCoeff() > 0.0) {
    Eigen::VectorXd x;
    Eigen::VectorXd y;
    k.solveWithMultipliers(a.transpose() * r.lambda, x, y);
    ddu += x;
    if (y.size() == dlambda.size()) {
      dlambda += y;
    }
  }
  mu_ = r.lambda;
  for (Eigen::Index i = 0; i < m; ++i) {
    muLink_[static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)])] = mu_(i);
  }
  solves_ += k.solves;
  addContactIterations(r.iterations);
  noteActive_ = r.activeLinks;
  notePenetration_ = r.maxInterpenetration;
}

std::vector<LinkState> DualContactConstraint::resolvedStates(const Eigen::VectorXd& u) const {
  const Eigen::VectorXd gaps = gapsAt(u);
  std::vector<LinkState> states(rows_.link.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    states[i].gap = gaps(row);
    states[i].normalForce = mu_(row);
    states[i].status = mu_(row) != 0.0 ? LinkStatus::Sliding : LinkStatus::Open;
  }
  return states;
}

void DualContactConstraint::accepted(const std::vector<LinkState>& rowStates) {
  for (std::size_t i = 0; i < rowStates.size(); ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[i]);
    if (definition_->zones[static_cast<std::size_t>(links_[k].zone)].slide &&
        rowStates[i].normalForce != 0.0) {
      bilateral_[k] = 1;
    }
  }
}

} // namespace stella::contact
