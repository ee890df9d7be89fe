#pragma once
// One facade for every linear solver of SOLVEUR (METHODE='MUMPS', 'MULT_FRONT', 'LDLT',
// 'GCPC'): analyse the pattern once, factorise the values at each Newton iteration, solve for
// one or a block of right-hand sides as many times as needed (contact sub-iterations reuse the
// factorisation).
//
// Backends by matrix kind:
//   MUMPS       symmetric, positive definite or indefinite e.g. with Lagrange multipliers
//               (SYM=2, as code_aster), unsymmetric (SYM=0); PCENT_PIVOT = ICNTL(14), RENUM = ICNTL(7),
//               null pivots detected with ICNTL(24) and CNTL(3) = 10^-NPREC.
//   MULT_FRONT, LDLT (SuiteSparse)  CHOLMOD supernodal LL^T when symmetric positive definite;
//               UMFPACK LU when symmetric indefinite (dualised Lagrange multipliers make the
//               matrix indefinite; an LDL^T without pivoting can meet a zero pivot) or unsymmetric.
//   GCPC        conjugate gradient, symmetric positive definite only (constraints must be
//               eliminated, AFFE_CHAR_CINE): PRE_COND='LDLT_INC' Eigen's with an incomplete
//               Cholesky; 'LDLT_SP' preconditioned by a single-precision MUMPS factorisation.
//   PETSC       a PETSc Krylov solver (ALGORITHME) and preconditioner (PRE_COND: GAMG, BOOMER,
//               ML, LDLT_SP, LDLT_INC, SOR, JACOBI, SANS) in the worker process `stella-petsc`
//               (PetscSolver.cpp); symmetric positive definite, or unsymmetric with GMRES,
//               FGMRES or GCR; the multigrids get the rigid-body modes (setNodeCoordinates).
// A singular matrix raises SingularMatrixError with the equation number of the null pivot.

#include "solver/linalg/MumpsControls.hpp"
#include "solver/linalg/SparseMatrix.hpp"

#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace stella::linalg {

enum class MatrixKind { SymmetricPositiveDefinite, SymmetricIndefinite, Unsymmetric };
enum class SolverMethod { Mumps, MultFront, Ldlt, Gcpc, Petsc };

std::optional<SolverMethod> solverMethodFromName(std::string_view name); // 'MUMPS', ...

struct SolverOptions {
  SolverMethod method = SolverMethod::Mumps;
  double pivotPercent = 20.0;              // PCENT_PIVOT
  std::string renumbering = "AUTO";        // RENUM: AUTO, AMD, AMF, PORD, METIS, QAMD, SCOTCH
  int nprec = 8;                           // NPREC: a pivot below 10^-NPREC (relative) is null
  bool stopIfSingular = true;              // STOP_SINGULIER
  double relativeResidual = 1e-6;          // RESI_RELA (GCPC)
  int maxIterations = 0;                   // NMAX_ITER (GCPC); 0: the system size
  std::string preconditioner = "LDLT_INC"; // PRE_COND (GCPC): LDLT_INC or LDLT_SP
  int preconditionerReuseIterations = 30;  // REAC_PRECOND (LDLT_SP): rebuilt after a solve needing more
  std::string algorithm = "FGMRES";        // ALGORITHME (PETSC): CG, GMRES, GCR, FGMRES
  int fillLevel = 0;                       // NIVE_REMPLISSAGE (PETSC, LDLT_INC)
  double fill = 1.0;                       // REMPLISSAGE (PETSC, LDLT_INC)
  std::string petscOptions;                // OPTION_PETSC: PETSc options database string
  MumpsControls mumps; // GESTION_MEMOIRE, ACCELERATION, LOW_RANK_SEUIL... (MUMPS and LDLT_SP)
};

// Whether this build has the PETSc worker (METHODE='PETSC'); false: refused at the keyword.
bool petscAvailable();

// The matrix is singular: `equation` is the null pivot's equation (-1 if the backend could not
// tell), to be named as node and DOF through the DofMap (SaddleSolver: SOLVE_1).
class SingularMatrixError : public std::runtime_error {
public:
  SingularMatrixError(std::string backend, int equation)
      : std::runtime_error(backend + ": singular matrix (null pivot at equation " + std::to_string(equation) +
                           ")"),
        backend_(std::move(backend)), equation_(equation) {}
  int equation() const { return equation_; }
  const std::string& backend() const { return backend_; }

private:
  std::string backend_;
  int equation_;
};

// Any other failure of a solver (memory, non-convergence of GCPC, unsupported combination).
class LinearSolverError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

class LinearSolver {
public:
  virtual ~LinearSolver() = default;
  virtual std::string_view backendName() const = 0;
  MatrixKind kind() const { return kind_; }
  // Symbolic analysis (ordering) of the matrix's pattern; values are not read.
  virtual void analyse(const SparseMatrix& a) = 0;
  // Numerical factorisation of a matrix with the analysed pattern.
  virtual void factorise(const SparseMatrix& a) = 0;
  // Solves in place for every column of `rhs` (n x k) with the last factorisation.
  virtual void solve(Eigen::Ref<Eigen::MatrixXd> rhs) = 0;
  // The next factorisations' matrices carry penalty terms `ratio` (>= 1) times the structure's
  // largest stiffness: a pivot is null below 10^-NPREC of the structure's stiffness, i.e. of the
  // matrix's largest term divided by `ratio` (else a penalty 1e7 times the stiffness makes the
  // structure's own pivots look null at NPREC = 8).
  void setPenaltyRatio(double ratio) { penaltyRatio_ = ratio > 1.0 ? ratio : 1.0; }
  // Floating-point operations of the last factorisation as the backend counts them (CHOLMOD:
  // cholmod_common::fl of the analysis, exact for LL^T; MUMPS: RINFOG(3); UMFPACK: its
  // UMFPACK_FLOPS), 0 before any factorisation. Divided by the factorisation's time it gives
  // the achieved rate that doc/bench/factor-rate.md compares with dgemm's.
  virtual double factorisationFlops() const = 0;
  // The fill-reducing ordering the last analysis used, named as RENUM names it (AMD, METIS...).
  virtual std::string orderingUsed() const = 0;
  // Node coordinates for the near-null space of the multigrid preconditioners (PETSC: GAMG, ML,
  // BOOMER get the rigid-body modes, 3 in 2D, 6 in 3D): `dimension` consecutive equations per
  // node, coordinates[e] the node's coordinate along equation e's component, for the physical
  // equations of a matrix without multiplier rows. The direct solvers have no use for them.
  virtual void setNodeCoordinates(int dimension, std::vector<double> coordinates) {
    (void)dimension;
    (void)coordinates;
  }
  // Iterations of the last solve (the largest over its right-hand sides); 0 for direct solvers.
  virtual int lastIterations() const { return 0; }
  // Peak resident memory (MB) of a process the backend runs in (PETSC's worker), 0 if none: the
  // job's own peak memory does not include it.
  virtual double workerPeakMegabytes() const { return 0.0; }
  // What the backend did in the last factorisation and solve, one line for the message file
  // (MUMPS: in/out of core, full rank or BLR, flops, factor entries, memory; GCPC: iterations).
  virtual std::string summary() const { return {}; }
  // MUMPS's INFOG(i) (1-based) of the last operation, 0 for other backends: what the tests read
  // to see that an option reached MUMPS.
  virtual long long mumpsInfog(int /*i*/) const { return 0; }

protected:
  explicit LinearSolver(MatrixKind k) : kind_(k) {}
  double penaltyRatio_ = 1.0;

private:
  MatrixKind kind_;
};

// Storage a kind needs: Upper for symmetric kinds, Full for unsymmetric.
inline Storage storageFor(MatrixKind k) {
  return k == MatrixKind::Unsymmetric ? Storage::Full : Storage::Upper;
}

// Throws LinearSolverError for combinations not available (GCPC on indefinite or unsymmetric
// matrices, PETSC on indefinite ones or without the worker).
std::unique_ptr<LinearSolver> makeLinearSolver(const SolverOptions& options, MatrixKind kind);

} // namespace stella::linalg
