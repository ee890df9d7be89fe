// Penalised contact and Coulomb friction: forces, statuses and tangent contributions, and a
// Newton loop on a given stiffness for standalone use and tests.

#include "solver/contact/PenaltyContact.hpp"

#include <cmath>

namespace stella::contact {

namespace {

using Eigen::Index;
using Eigen::VectorXd;

// Adds c * (row a)^T (row b) to the triplets.
void addOuter(std::vector<Eigen::Triplet<double>>& t, const SparseRows& ra, Index a, const SparseRows& rb,
              Index b, double c) {
  for (SparseRows::InnerIterator i(ra, a); i; ++i) {
    for (SparseRows::InnerIterator j(rb, b); j; ++j) {
      t.emplace_back(static_cast<int>(i.col()), static_cast<int>(j.col()), c * i.value() * j.value());
    }
  }
}

} // namespace

PenaltyEvaluation evaluatePenalty(const ContactProblem& p, const FrictionRows* fr,
                                  const PenaltyParameters& par, const VectorXd& du) {
  const Index m = p.A.rows();
  PenaltyEvaluation e;
  e.force = VectorXd::Zero(p.A.cols());
  e.normalForce = VectorXd::Zero(m);
  e.frictionForce = Eigen::MatrixXd::Zero(m, 2);
  e.slip = Eigen::MatrixXd::Zero(m, 2);
  e.status.assign(static_cast<std::size_t>(m), LinkStatus::Open);
  const VectorXd gap = p.gap + p.A * du;
  const bool withFriction = par.friction && fr != nullptr;
  const bool threeD = withFriction && fr->T2.rows() > 0;
  VectorXd s1;
  VectorXd s2;
  if (withFriction) {
    s1 = fr->T1 * du;
    s2 = threeD ? VectorXd(fr->T2 * du) : VectorXd::Zero(m);
    if (par.slipOffset.rows() == m) {
      s1 += par.slipOffset.col(0);
      s2 += par.slipOffset.col(1);
    }
  }
  for (Index i = 0; i < m; ++i) {
    if (!(gap(i) < 0.0) && !p.isBilateral(i)) {
      continue;
    }
    const double en = par.normalPenalty(i);
    const double lambda = -en * gap(i);
    e.normalForce(i) = lambda;
    e.maxInterpenetration = std::max(e.maxInterpenetration, -gap(i));
    ++e.activeLinks;
    for (SparseRows::InnerIterator it(p.A, i); it; ++it) {
      e.force(it.col()) += lambda * it.value();
    }
    addOuter(e.tangent, p.A, i, p.A, i, en);
    e.status[static_cast<std::size_t>(i)] = LinkStatus::Sliding; // frictionless contact: 2
    if (!withFriction) {
      continue;
    }
    const double et = par.tangentPenalty(i);
    const double mu = par.coulomb(i);
    const double sx = s1(i);
    const double sy = s2(i);
    e.slip(i, 0) = sx;
    e.slip(i, 1) = sy;
    const double slip = std::hypot(sx, sy);
    double t1 = -et * sx;
    double t2 = -et * sy;
    if (et * slip <= mu * std::max(lambda, 0.0)) {
      e.status[static_cast<std::size_t>(i)] = LinkStatus::Sticking;
      addOuter(e.tangent, fr->T1, i, fr->T1, i, et);
      if (threeD) {
        addOuter(e.tangent, fr->T2, i, fr->T2, i, et);
      }
    } else {
      const double nx = sx / slip;
      const double ny = sy / slip;
      t1 = -mu * lambda * nx;
      t2 = -mu * lambda * ny;
      const double c = par.matrixCoefficient(i);
      if (c != 0.0 && mu != 0.0) { // COULOMB = 0: no force, no tangent
        // c * [ mu lambda/|s| T^T (I - n n^T) T - mu E_N T^T n A ].
        const double k = c * mu * lambda / slip;
        addOuter(e.tangent, fr->T1, i, fr->T1, i, k * (1.0 - nx * nx));
        addOuter(e.tangent, fr->T1, i, p.A, i, -c * mu * en * nx);
        if (threeD) {
          addOuter(e.tangent, fr->T2, i, fr->T2, i, k * (1.0 - ny * ny));
          addOuter(e.tangent, fr->T1, i, fr->T2, i, -k * nx * ny);
          addOuter(e.tangent, fr->T2, i, fr->T1, i, -k * nx * ny);
          addOuter(e.tangent, fr->T2, i, p.A, i, -c * mu * en * ny);
        }
        e.symmetric = false;
      }
    }
    e.frictionForce(i, 0) = t1;
    e.frictionForce(i, 1) = t2;
    for (SparseRows::InnerIterator it(fr->T1, i); it; ++it) {
      e.force(it.col()) += t1 * it.value();
    }
    if (threeD) {
      for (SparseRows::InnerIterator it(fr->T2, i); it; ++it) {
        e.force(it.col()) += t2 * it.value();
      }
    }
  }
  return e;
}

PenaltyNewtonResult solvePenaltyNewton(const Eigen::SparseMatrix<double>& k, const VectorXd& f,
                                       const ContactProblem& p, const FrictionRows* fr,
                                       const PenaltyParameters& par, const SparseSolve& solve,
                                       int maxIterations, double relativeTolerance) {
  PenaltyNewtonResult r;
  r.du = VectorXd::Zero(f.size());
  const double reference = std::max(f.norm(), 1e-300);
  for (r.iterations = 0; r.iterations < maxIterations; ++r.iterations) {
    r.state = evaluatePenalty(p, fr, par, r.du);
    const VectorXd residual = f + r.state.force - k * r.du;
    if (r.iterations > 0 && residual.norm() <= relativeTolerance * reference) {
      r.converged = true;
      break;
    }
    Eigen::SparseMatrix<double> contact(k.rows(), k.cols());
    contact.setFromTriplets(r.state.tangent.begin(), r.state.tangent.end());
    const Eigen::SparseMatrix<double> tangent = k + contact;
    r.usedUnsymmetric = r.usedUnsymmetric || !r.state.symmetric;
    r.du += solve(tangent, residual, r.state.symmetric);
  }
  return r;
}

} // namespace stella::contact
