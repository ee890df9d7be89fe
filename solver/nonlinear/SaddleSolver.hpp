#pragma once
// Solution of the linearised mechanical system with dualised constraints and eliminated DOFs:
//
//   [ K    s C^T ] [ du ]   [ r     ]        lambda = s mu (the multipliers, in force units)
//   [ s C  0     ] [ mu ] = [ s g   ]
//
// One Lagrange multiplier per linear relation (not code_aster's double Lagrange): the matrix is
// symmetric indefinite, so it goes to the SOLVEUR's solver as such (MUMPS SYM=2 by default,
// UMFPACK for MULT_FRONT/LDLT; CHOLMOD when there is no multiplier; unsymmetric storage when a
// tangent is unsymmetric); s is the mean of |diag K| so that both blocks have the same magnitude. DOFs
// imposed by AFFE_CHAR_CINE are eliminated (unit diagonal, prescribed value moved to the right-hand side).
//
// A singular system is diagnosed before it can produce garbage: the SPD matrix
// K + s C^T C (with eliminated DOFs removed) is factorised with LDL^T; a pivot that loses more
// than 8 digits relative to its diagonal names the node and component left free (UserError
// SOLVE_1, the message code_aster's STOP_SINGULIER gives, in words). The factorisation is kept
// for further right-hand sides (contact sub-iterations, line search).

#include "solver/mesh/Mesh.hpp"
#include "solver/nonlinear/DofMap.hpp"

#include "solver/linalg/LinearSolver.hpp"
#include <Eigen/Sparse>
#include <memory>
#include <vector>

namespace stella {

struct ConstraintRow {
  std::vector<std::pair<int, double>> terms; // (physical equation, coefficient)
};

class SaddleSolver {
public:
  // `eliminated[i]` for physical equations imposed by elimination.
  SaddleSolver(const DofMap& dofs, const Mesh& mesh, std::vector<ConstraintRow> rows,
               std::vector<bool> eliminated);

  // SOLVEUR options (METHODE, RENUM, NPREC, PCENT_PIVOT...); MUMPS by default.
  void setOptions(const linalg::SolverOptions& options) { options_ = options; }
  const linalg::SolverOptions& options() const { return options_; }
  // "MUMPS" etc., after the first factorisation.
  std::string backendName() const;

  // Factorises for the tangent K (physical block; `symmetric` chooses the storage). `checkSingular`
  // runs the pivot check first (always done when the solver reports a null pivot). Throws
  // UserError SOLVE_1 (singular, naming the DOF) / SOLVE_2 (other solver failures).
  void factorize(const Eigen::SparseMatrix<double>& k, bool checkSingular, bool symmetric = true);

  // Solves with the last factorisation. `r` (physical), `g` (one per row), `prescribed` (the
  // increments of the eliminated DOFs, physical size). Throws UserError SOLVE_3 on a non-finite
  // solution.
  void solve(const Eigen::VectorXd& r, const Eigen::VectorXd& g, const Eigen::VectorXd& prescribed,
             Eigen::VectorXd& du, Eigen::VectorXd& dlambda);

  // C^T lambda (physical size): the reactions of the multipliers.
  Eigen::VectorXd transposeTimes(const Eigen::VectorXd& lambda) const;
  // C u (one per row).
  Eigen::VectorXd times(const Eigen::VectorXd& u) const;

  const std::vector<bool>& eliminated() const { return eliminated_; }
  int factorizations() const { return factorizations_; }

private:
  void checkSingularity(const Eigen::SparseMatrix<double>& k) const;

  const DofMap& dofs_;
  const Mesh& mesh_;
  std::vector<ConstraintRow> rows_;
  std::vector<bool> eliminated_;
  Eigen::SparseMatrix<double> k_; // the physical block of the last factorisation
  double scale_ = 1.0;
  linalg::SolverOptions options_;
  std::unique_ptr<linalg::LinearSolver> solver_;
  std::shared_ptr<const linalg::SparsePattern> pattern_;
  int factorizations_ = 0;
};

} // namespace stella
