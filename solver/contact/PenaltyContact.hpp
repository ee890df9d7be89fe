#pragma once
// Penalised discrete contact and Coulomb friction (ALGO_CONT='PENALISATION' with E_N,
// ALGO_FROT='PENALISATION' with E_T, COULOMB, COEF_MATR_FROT; notice §3.2.2, §3.3.2).
//
// For a displacement increment du (since the pairing) with gap(du) = g + A du:
//   normal force     lambda = E_N max(0, -gap)             (compressive positive)
//   slip             s = [T1 du, T2 du]                      (relative tangential displacement)
//   friction force   t = -E_T s if E_T |s| <= mu lambda    (sticking, CONT = 1)
//                    t = -mu lambda s/|s| otherwise        (sliding,  CONT = 2)
// The contact force on the structure is f = A^T lambda + T1^T t1 + T2^T t2 and the residual
// K du - F - f(du) = 0. Tangent contributions (added to K): E_N A_i^T A_i on active links;
// E_T T^T T on sticking links; on sliding links COEF_MATR_FROT times the consistent tangent
// mu lambda/|s| T^T (I - s s^T/|s|^2) T - mu E_N T^T (s/|s|) A_i, which is unsymmetric (the
// friction force depends on the normal force). Without friction, or with COEF_MATR_FROT = 0, the
// contributions are symmetric.

#include "solver/contact/DiscreteContact.hpp"

#include <functional>
#include <vector>

namespace stella::contact {

struct PenaltyParameters {
  Eigen::VectorXd normalPenalty; // E_N per link
  bool friction = false;
  Eigen::VectorXd tangentPenalty;    // E_T per link
  Eigen::VectorXd coulomb;           // mu per link
  Eigen::VectorXd matrixCoefficient; // COEF_MATR_FROT per link
  // Slip already there at du = 0 (links x 2; empty: none): the slip is s = [T1 du, T2 du] +
  // slipOffset. STAT_NON_LINE puts there the slip since the step start not seen by du and the
  // elastic slip -t/E_T left by the previous step (incremental friction).
  Eigen::MatrixXd slipOffset;
};

struct FrictionRows {
  SparseRows T1; // links x DOFs
  SparseRows T2; // empty (0 rows) in 2D
};

enum class LinkStatus : int { Open = 0, Sticking = 1, Sliding = 2 };

struct PenaltyEvaluation {
  Eigen::VectorXd force;                       // f (DOFs)
  std::vector<Eigen::Triplet<double>> tangent; // contributions to add to K
  bool symmetric = true;
  Eigen::VectorXd normalForce;   // lambda per link
  Eigen::MatrixXd frictionForce; // links x 2 (t1, t2)
  Eigen::MatrixXd slip;          // links x 2
  std::vector<LinkStatus> status;
  int activeLinks = 0;
  double maxInterpenetration = 0.0;
};

PenaltyEvaluation evaluatePenalty(const ContactProblem& problem, const FrictionRows* friction,
                                  const PenaltyParameters& parameters, const Eigen::VectorXd& du);

// Solves K du = F + f(du) by Newton with the penalty tangent: `solve(matrix, rhs, symmetric)`
// factorises and solves (the caller chooses the factorisation; symmetric when told so).
struct PenaltyNewtonResult {
  Eigen::VectorXd du;
  PenaltyEvaluation state;
  int iterations = 0;
  bool converged = false;
  bool usedUnsymmetric = false;
};

using SparseSolve =
    std::function<Eigen::VectorXd(const Eigen::SparseMatrix<double>&, const Eigen::VectorXd&, bool)>;

PenaltyNewtonResult solvePenaltyNewton(const Eigen::SparseMatrix<double>& k, const Eigen::VectorXd& f,
                                       const ContactProblem& problem, const FrictionRows* friction,
                                       const PenaltyParameters& parameters, const SparseSolve& solve,
                                       int maxIterations = 50, double relativeTolerance = 1e-10);

} // namespace stella::contact
