// GCPC with PRE_COND='LDLT_SP': conjugate gradient in double precision, preconditioned by a
// single-precision MUMPS factorisation of the same matrix (code_aster's LDLT_SP). The
// preconditioner is kept across factorisations (Newton iterations) while the solves it serves
// converge within REAC_PRECOND iterations; the next factorisation after one that needed more
// rebuilds it (code_aster's REAC_PRECOND). Symmetric positive definite matrices only.

#include "solver/linalg/Backends.hpp"
#include "solver/linalg/MumpsControlsApply.hpp"
#include "solver/linalg/MumpsCoordinates.hpp"
#include "solver/linalg/MumpsFactorise.hpp"
#include "solver/parallel/Mpi.hpp"

#include <smumps_c.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace stella::linalg::detail {
namespace {

constexpr int jobInit = -1, jobEnd = -2, jobAnalyse = 1, jobSolve = 3;

class SinglePrecisionPcg final : public LinearSolver {
public:
  explicit SinglePrecisionPcg(const SolverOptions& o)
      : LinearSolver(MatrixKind::SymmetricPositiveDefinite), options_(o) {
    id_ = {};
    // Under MPI each process keeps its own preconditioner (the CG runs on every process alike).
    id_.comm_fortran = mpi::fortranSelf();
    id_.par = 1;
    id_.sym = 1; // SPD: LL^T without pivoting
    id_.job = jobInit;
    smumps_c(&id_);
    if (id_.infog[0] < 0) {
      throw LinearSolverError("GCPC LDLT_SP: MUMPS initialisation failed");
    }
    initialised_ = true;
    id_.icntl[0] = id_.icntl[1] = id_.icntl[2] = -1;
    id_.icntl[3] = 0;
    if (o.renumbering != "SANS" && o.renumbering != "AUTO") {
      throw LinearSolverError("GCPC LDLT_SP: RENUM='" + o.renumbering +
                              "' is not available (SANS: MUMPS's choice)");
    }
    id_.icntl[6] = 7;                                              // ICNTL(7): MUMPS's choice
    id_.icntl[13] = static_cast<int>(std::lround(o.pivotPercent)); // ICNTL(14) = PCENT_PIVOT
    applyMumpsControls(id_, o.mumps); // LOW_RANK_SEUIL (block low-rank preconditioner)
    id_.icntl[9] = 0;                 // no iterative refinement of the preconditioner
    id_.icntl[10] = 0;
  }
  ~SinglePrecisionPcg() override {
    if (initialised_) {
      id_.job = jobEnd;
      smumps_c(&id_);
    }
  }
  SinglePrecisionPcg(const SinglePrecisionPcg&) = delete;
  SinglePrecisionPcg& operator=(const SinglePrecisionPcg&) = delete;

  std::string_view backendName() const override { return "GCPC (LDLT_SP)"; }
  double factorisationFlops() const override { return factorisations_ > 0 ? id_.rinfog[2] : 0.0; }
  std::string orderingUsed() const override { return "none"; }
  std::string summary() const override {
    return factorisations_ > 0
               ? "preconditioner " + mumpsSummary(id_, options_.mumps) + " (single precision), " +
                     std::to_string(lastIterations_) + " conjugate gradient iterations"
               : "";
  }
  long long mumpsInfog(int i) const override { return id_.infog[i - 1]; }
  int preconditionerFactorisations() const { return factorisations_; }

  void analyse(const SparseMatrix& a) override {
    if (a.storage() != Storage::Upper) {
      throw LinearSolverError("GCPC LDLT_SP: needs upper-triangle storage");
    }
    const SparsePattern& p = a.pattern();
    mumpsCoordinates(p, irn_, jcn_);
    id_.n = p.size;
    id_.nnz = p.nonZeros();
    id_.irn = irn_.data();
    id_.jcn = jcn_.data();
    id_.a = nullptr;
    id_.job = jobAnalyse;
    smumps_c(&id_);
    check("analysis");
    chooseMumpsMemory(id_, options_.mumps);
    rebuild_ = true;
  }

  void factorise(const SparseMatrix& a) override {
    matrix_ = a;
    if (!rebuild_) {
      return; // the preconditioner of an earlier matrix still serves (REAC_PRECOND)
    }
    values_.assign(a.values().begin(), a.values().end());
    id_.a = values_.data();
    factoriseWithWorkspaceRetries(id_, smumps_c);
    if (id_.infog[0] == -10) {
      throw SingularMatrixError("GCPC LDLT_SP", -1);
    }
    check("factorisation");
    ++factorisations_;
    rebuild_ = false;
  }

  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override {
    if (!matrix_ || rhs.rows() != id_.n) {
      throw LinearSolverError("GCPC LDLT_SP: solve before factorisation or of the wrong size");
    }
    for (Eigen::Index c = 0; c < rhs.cols(); ++c) {
      rhs.col(c) = conjugateGradient(rhs.col(c));
    }
  }

private:
  // z = M^-1 r through the single-precision factors.
  Eigen::VectorXd precondition(const Eigen::VectorXd& r) {
    Eigen::VectorXf z = r.cast<float>();
    id_.rhs = z.data();
    id_.nrhs = 1;
    id_.lrhs = id_.n;
    id_.job = jobSolve;
    smumps_c(&id_);
    check("preconditioner solve");
    return z.cast<double>();
  }

  Eigen::VectorXd conjugateGradient(const Eigen::VectorXd& b) {
    const double bNorm = b.norm();
    Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
    if (bNorm == 0.0) {
      return x;
    }
    const int maxIterations = options_.maxIterations > 0 ? options_.maxIterations : id_.n;
    Eigen::VectorXd r = b;
    Eigen::VectorXd z = precondition(r);
    Eigen::VectorXd p = z;
    double rz = r.dot(z);
    for (int k = 1; k <= maxIterations; ++k) {
      const Eigen::VectorXd q = matrix_->multiply(p);
      const double alpha = rz / p.dot(q);
      x += alpha * p;
      r -= alpha * q;
      if (r.norm() <= options_.relativeResidual * bNorm) {
        lastIterations_ = k;
        rebuild_ = rebuild_ || k > options_.preconditionerReuseIterations;
        return x;
      }
      z = precondition(r);
      const double rzNext = r.dot(z);
      p = z + (rzNext / rz) * p;
      rz = rzNext;
    }
    rebuild_ = true;
    throw LinearSolverError("GCPC LDLT_SP: no convergence in " + std::to_string(maxIterations) +
                            " iterations (relative residual " + std::to_string(r.norm() / bNorm) + ")");
  }

  void check(const char* phase) const {
    if (id_.infog[0] < 0) {
      throw LinearSolverError(std::string("GCPC LDLT_SP: MUMPS ") + phase +
                              " failed (INFOG(1) = " + std::to_string(id_.infog[0]) + ")");
    }
  }

  SolverOptions options_;
  SMUMPS_STRUC_C id_;
  bool initialised_ = false;
  bool rebuild_ = true;
  int factorisations_ = 0;
  int lastIterations_ = 0;
  std::optional<SparseMatrix> matrix_; // the matrix of the last factorisation (CG's operator)
  std::vector<MUMPS_INT> irn_, jcn_;
  std::vector<float> values_;
};

} // namespace

std::unique_ptr<LinearSolver> makeSinglePrecisionPcg(const SolverOptions& o) {
  return std::make_unique<SinglePrecisionPcg>(o);
}

} // namespace stella::linalg::detail
