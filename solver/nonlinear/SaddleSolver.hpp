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
// A relation on a single DOF (DDL_IMPO, FACE_IMPO, a one-term LIAISON_DDL: c u_j = g) whose DOF no
// other relation holds is eliminated the same way (u_j = g / c) instead of being dualised, and its
// multiplier is recovered after the solve from row j of the first block: lambda = (r_j - K_j du) / c.
// So a study whose relations are all of that kind gives an SPD matrix (CHOLMOD for MULT_FRONT/LDLT,
// MUMPS SYM=1, GCPC accepted); only the other relations keep a multiplier row. The solution and the
// multipliers are those of the dualised system (condenseSingleDofRelations(false) keeps the former
// path: tests and the benchmark compare both).
//
// The bordered matrix is built in compressed rows straight from the in-place assembled K
// (StiffnessMatrix): its pattern is computed once and rebuilt, with the solver's symbolic
// analysis, only when K's pattern (penalised contact pairs), the storage or the matrix kind
// changes; at the other factorisations only the values are copied.
//
// A singular system is detected by the backend during the factorisation (MUMPS null pivots,
// ICNTL(24) with CNTL(3) = 10^-NPREC; CHOLMOD not positive definite; UMFPACK singular), and only
// then diagnosed: the SPD matrix K + s C^T C (with eliminated DOFs removed) is factorised with
// LDL^T and a pivot that loses more than 8 digits relative to its diagonal names the node and
// component left free (UserError SOLVE_1, the message code_aster's STOP_SINGULIER gives, in
// words). The factorisation is kept for further right-hand sides (contact sub-iterations, line
// search). On request, a factorize() call with the values already factorised keeps the factors.

#include "solver/assembly/DofMap.hpp"
#include "solver/assembly/StiffnessMatrix.hpp"
#include "solver/mesh/Mesh.hpp"

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
  // Iterations of the last solve of an iterative backend (PETSC), 0 for direct ones.
  int lastIterations() const { return solver_ ? solver_->lastIterations() : 0; }
  // Peak memory (MB) of the backend's worker process (PETSC), 0 if none.
  double workerPeakMegabytes() const { return solver_ ? solver_->workerPeakMegabytes() : 0.0; }
  // The backend's one-line account of its last factorisation and solve (empty if none).
  std::string backendSummary() const;
  // MUMPS's INFOG(i) of the last operation (0 for other backends or before any).
  long long mumpsInfog(int i) const;

  // Factorises for the tangent K (physical block, assembled in place; `symmetric` chooses the
  // storage and K must then be stored upper or full, else full). Throws UserError SOLVE_1
  // (singular, naming the DOF) / SOLVE_2 (other solver failures).
  void factorize(const StiffnessMatrix& k, bool symmetric = true);
  // The same for a K given as an Eigen matrix (tests, small systems). `checkSingular` runs the
  // singularity diagnosis before the factorisation (slow: 10 to 15 times a supernodal
  // factorisation; without it, it runs only when the backend finds a null pivot).
  void factorize(const Eigen::SparseMatrix<double>& k, bool checkSingular, bool symmetric = true);
  // Penalty terms in the next matrices, `ratio` times the structure's largest stiffness: null
  // pivots are judged against the structure's stiffness (linalg::LinearSolver::setPenaltyRatio).
  void setPenaltyRatio(double ratio) { penaltyRatio_ = ratio; }

  // Seconds spent so far (phase report of the log): building the bordered matrix, symbolic
  // analyses, numerical factorisations, solutions.
  struct Timings {
    double bordering = 0.0;
    double analysis = 0.0;
    double factorisation = 0.0;
    double solve = 0.0;
    int analyses = 0;
  };
  const Timings& timings() const { return timings_; }

  // Solves with the last factorisation. `r` (physical), `g` (one per row), `prescribed` (the
  // increments of the eliminated DOFs, physical size). Throws UserError SOLVE_3 on a non-finite
  // solution.
  void solve(const Eigen::VectorXd& r, const Eigen::VectorXd& g, const Eigen::VectorXd& prescribed,
             Eigen::VectorXd& du, Eigen::VectorXd& dlambda);

  // Solves K x = b for the columns of `rhs` (physical size) in ONE call of the backend, with
  // homogeneous relations and zero prescribed increments (the Schur columns of discrete
  // contact, NB_RESOL per call); `rhs` is overwritten by the physical part of the solutions.
  void solveHomogeneous(Eigen::Ref<Eigen::MatrixXd> rhs);

  // C^T lambda (physical size): the reactions of the multipliers.
  Eigen::VectorXd transposeTimes(const Eigen::VectorXd& lambda) const;
  // C u (one per row).
  Eigen::VectorXd times(const Eigen::VectorXd& u) const;

  // The DOFs imposed by AFFE_CHAR_CINE (not those of the single-DOF relations eliminated here,
  // which keep their multipliers in solve()).
  const std::vector<bool>& eliminated() const { return eliminated_; }
  // Eliminates the single-DOF relations (default) or dualises every relation (the former path);
  // before the first factorize().
  void condenseSingleDofRelations(bool condense) { condense_ = condense; }
  // Relations that keep a multiplier row in the factorised matrix (after the first factorize()).
  int borderedRelationCount() const { return static_cast<int>(keptRows_.size()); }
  int factorizations() const { return factorizations_; }
  // With `keep`, factorize() compares the values with those it last factorised and keeps the
  // factors when they are equal (STAT_NON_LINE: elastic bodies under dual contact); it holds a
  // copy of the values for that, so a single solve (MECA_STATIQUE) leaves it off.
  void keepFactorsOfUnchangedMatrix(bool keep) {
    keepUnchanged_ = keep;
    factorisedValues_.clear();
  }
  // Calls of factorize() that found the values already factorised and kept the factors (not
  // counted in factorizations()).
  int reusedFactorizations() const { return reusedFactorizations_; }

private:
  // Solves the bordered system in place with the last factorisation (timed); SOLVE_3 on a
  // non-finite solution.
  void solveBordered(Eigen::Ref<Eigen::MatrixXd> x);
  void checkSingularity(const Eigen::SparseMatrix<double>& k) const;
  std::vector<double> equationCoordinates() const;
  // Chooses the single-DOF relations to eliminate (condensed_, removed_, keptRows_); then per
  // physical DOF, the (kept relation, coefficient) of the kept relations holding it (free DOFs
  // only); per kept relation, its (DOF, coefficient) terms on free DOFs, sorted and merged.
  void prepareRelations();
  // The single-DOF relations c u_j = g to eliminate: j is not eliminated and no other relation holds it.
  void chooseCondensedRelations(const std::vector<std::vector<std::pair<int, double>>>& merged);
  // Visits the bordered matrix row by row: entry(column, value) in increasing column order,
  // rowEnd(row) after each row.
  template <class Entry, class RowEnd>
  void walk(const StiffnessMatrix& k, linalg::Storage storage, Entry&& entry, RowEnd&& rowEnd) const;
  // Builds (or refills) the bordered matrix for K; true when its pattern changed.
  bool border(const StiffnessMatrix& k, linalg::Storage storage);
  // K's entries coupling a DOF to an eliminated DOF, by column (moves prescribed values to the
  // right-hand side).
  void extractEliminatedColumns(const StiffnessMatrix& k);

  const DofMap& dofs_;
  const Mesh& mesh_;
  std::vector<ConstraintRow> rows_;
  std::vector<bool> eliminated_;
  bool condense_ = true;
  struct Condensed {
    int row;
    int dof;
    double coefficient;
  };
  std::vector<Condensed> condensed_;              // the single-DOF relations eliminated
  std::vector<bool> removed_;                     // eliminated_ and the DOFs of condensed_
  std::vector<int> keptRows_;                     // the relations with a multiplier row, in order
  Eigen::SparseMatrix<double> eliminatedColumns_; // K(:, removed) of the last factorisation
  Eigen::SparseMatrix<double> condensedRows_;     // K(j, :) for the DOFs of condensed_
  bool anyEliminated_ = false;
  double scale_ = 1.0;
  linalg::SolverOptions options_;
  std::unique_ptr<linalg::LinearSolver> solver_;
  double penaltyRatio_ = 1.0;
  linalg::SparseMatrix bordered_;                             // the matrix of the last factorisation
  std::uint64_t borderedFor_ = 0;                             // StiffnessMatrix::patternId() it was built for
  std::shared_ptr<const linalg::SparsePattern> analysed_;     // the pattern of the solver's analysis
  std::vector<std::int64_t> dofTermStart_;                    // per physical DOF into dofTerms_
  std::vector<std::pair<int, double>> dofTerms_;              // (relation, coefficient)
  std::vector<std::vector<std::pair<int, double>>> rowTerms_; // per relation: (DOF, coefficient)
  int factorizations_ = 0;
  int reusedFactorizations_ = 0;
  bool keepUnchanged_ = false;
  std::vector<double> factorisedValues_; // with keepUnchanged_: the values of the last factorisation
  Timings timings_;
};

} // namespace stella
