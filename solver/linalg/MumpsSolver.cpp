// MUMPS backend (double precision C interface): the sequential library, or the parallel one on
// the MPI world of the run (solver/parallel/Mpi.hpp). On more than one process the matrix goes
// to MUMPS distributed (ICNTL(18) = 3: each process gives its share of the entries, MUMPS sums
// duplicates), the right-hand sides on the host (rank 0), the solution comes back centralised on
// the host (ICNTL(21) = 0) and is broadcast to every process.

#include "solver/linalg/Backends.hpp"
#include "solver/linalg/MumpsControlsApply.hpp"
#include "solver/linalg/MumpsCoordinates.hpp"
#include "solver/linalg/MumpsFactorise.hpp"
#include "solver/linalg/MumpsOrderings.hpp"
#include "solver/parallel/Mpi.hpp"

#include <dmumps_c.h>

#include <cmath>
#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace stella::linalg {

bool mumpsOrderingAvailable(std::string_view renum) {
  return !(mpi::built() && renum == "SCOTCH");
}

} // namespace stella::linalg

namespace stella::linalg::detail {
namespace {

constexpr int jobInit = -1, jobEnd = -2, jobAnalyse = 1, jobSolve = 3;

// RENUM -> ICNTL(7). Debian 12's sequential MUMPS has no METIS (it falls back to its automatic
// choice: INFOG(7) tells), so the catalogue refuses RENUM='METIS' for MUMPS; PARMETIS and
// PTSCOTCH are parallel orderings (refused there too).
int orderingCode(const std::string& renum) {
  if (!mumpsOrderingAvailable(renum)) {
    throw LinearSolverError("MUMPS: RENUM='" + renum +
                            "' is not available in the parallel MUMPS of this build (built without "
                            "SCOTCH): AMD, AMF, PORD, QAMD or AUTO");
  }
  static const std::pair<const char*, int> codes[] = {{"AMD", 0},   {"AMF", 2},  {"SCOTCH", 3}, {"PORD", 4},
                                                      {"METIS", 5}, {"QAMD", 6}, {"AUTO", 7}};
  for (const auto& [name, code] : codes) {
    if (renum == name) {
      return code;
    }
  }
  throw LinearSolverError("MUMPS: RENUM='" + renum +
                          "' is not available (AMD, AMF, SCOTCH, PORD, QAMD or AUTO)");
}

std::string orderingName(int code) {
  switch (code) {
  case 0:
    return "AMD";
  case 1:
    return "USER";
  case 2:
    return "AMF";
  case 3:
    return "SCOTCH";
  case 4:
    return "PORD";
  case 5:
    return "METIS";
  case 6:
    return "QAMD";
  default:
    return "none";
  }
}

class MumpsSolver final : public LinearSolver {
public:
  MumpsSolver(const SolverOptions& o, MatrixKind k) : LinearSolver(k), options_(o) {
    const int ordering = orderingCode(o.renumbering); // before the instance exists: may throw
    id_ = {};
    id_.comm_fortran = mpi::fortranWorld();
    distributed_ = mpi::size() > 1;
    id_.par = 1;
    // SYM=2 (general symmetric) also for positive definite matrices: with SYM=1 the null-pivot
    // detection of ICNTL(24) let a floating structure through in our tests.
    id_.sym = k == MatrixKind::Unsymmetric ? 0 : 2;
    id_.job = jobInit;
    dmumps_c(&id_);
    if (id_.infog[0] < 0) {
      throw LinearSolverError("MUMPS: initialisation failed (INFOG(1) = " + std::to_string(id_.infog[0]) +
                              ")");
    }
    id_.icntl[0] = -1; // no error output
    id_.icntl[1] = -1;
    id_.icntl[2] = -1;
    id_.icntl[3] = 0;
    id_.icntl[6] = ordering;                                       // ICNTL(7)
    id_.icntl[17] = distributed_ ? 3 : 0;                          // ICNTL(18): distributed entries
    id_.icntl[13] = static_cast<int>(std::lround(o.pivotPercent)); // ICNTL(14)
    // ICNTL(24): null pivot detection, with the relative threshold CNTL(3) = 10^-NPREC; a
    // negative NPREC turns it off (code_aster's convention): MUMPS then only fails on a pivot
    // that is exactly zero (INFOG(1) = -10)
    id_.icntl[23] = o.nprec >= 0 ? 1 : 0;
    id_.cntl[2] = o.nprec >= 0 ? std::pow(10.0, -o.nprec) : 0.0;
    applyMumpsControls(id_, o.mumps); // GESTION_MEMOIRE, ACCELERATION, POSTTRAITEMENTS...
    initialised_ = true;
  }
  ~MumpsSolver() override {
    // JOB=-2 is collective: on several processes, an exception of this process alone (the others
    // inside a MUMPS call) would hang here; the instance is left to the end of the process.
    if (initialised_ && !(distributed_ && std::uncaught_exceptions() > 0)) {
      id_.job = jobEnd;
      dmumps_c(&id_);
    }
  }
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  std::string_view backendName() const override { return "MUMPS"; }
  double factorisationFlops() const override { return factorised_ ? id_.rinfog[2] : 0.0; } // RINFOG(3)
  std::string orderingUsed() const override { return orderingName(id_.infog[6]); }         // INFOG(7)
  std::string summary() const override {
    if (!factorised_) {
      return "";
    }
    std::string s = mumpsSummary(id_, options_.mumps);
    if (distributed_) { // the load balance of the last factorisation (RINFO(3), INFOG(21))
      s += ", on " + std::to_string(mpi::size()) + " processes: the busiest did " + fmtReal(busiestFlops_) +
           " flops and used " + std::to_string(id_.infog[20]) + " MB (INFOG(21))";
    }
    return s;
  }
  long long mumpsInfog(int i) const override { return id_.infog[i - 1]; }

  void analyse(const SparseMatrix& a) override {
    if (a.storage() != storageFor(kind())) {
      throw LinearSolverError("MUMPS: matrix storage does not match the matrix kind");
    }
    const SparsePattern& p = a.pattern();
    mumpsCoordinates(p, irn_, jcn_);
    id_.n = p.size;
    // The values of this matrix, for the analysis's numerical preprocessing (weighted matching and
    // scaling, 2x2 pivots of the multipliers). Never the pointer of an earlier factorisation: a
    // re-analysis after a pattern change read that stale array (INFOG(1) = -6 on penalised contact).
    const bool withValues = a.values().size() == irn_.size();
    if (distributed_) {
      giveLocalEntries(withValues ? a.values().data() : nullptr);
    } else {
      id_.nnz = p.nonZeros();
      id_.irn = irn_.data();
      id_.jcn = jcn_.data();
      id_.a = withValues ? const_cast<double*>(a.values().data()) : nullptr;
    }
    id_.job = jobAnalyse;
    dmumps_c(&id_);
    check("analysis");
    chooseMumpsMemory(id_, options_.mumps);
  }

  void factorise(const SparseMatrix& a) override {
    mpi::failIfInjected("the MUMPS factorisation"); // the test of a failure on one process
    if (distributed_) {
      giveLocalEntries(a.values().data());
    } else {
      id_.a = const_cast<double*>(a.values().data()); // MUMPS does not modify A
    }
    if (options_.nprec >= 0) {
      id_.cntl[2] = std::pow(10.0, -options_.nprec) / penaltyRatio_; // CNTL(3), see setPenaltyRatio
    }
    factoriseWithWorkspaceRetries(id_, dmumps_c); // too little workspace: relax the estimate, retry
    if (id_.infog[0] == -10) {
      throw SingularMatrixError("MUMPS", -1);
    }
    check("factorisation");
    factorised_ = true;
    if (distributed_) {
      busiestFlops_ = mpi::maxOver(id_.rinfo[2]); // RINFO(3): this process's factorisation flops
    }
    if (options_.stopIfSingular && id_.infog[27] > 0) { // INFOG(28): null pivots found
      int equation = mpi::rank() == 0 && id_.pivnul_list != nullptr ? id_.pivnul_list[0] - 1 : -1;
      mpi::broadcast(&equation, 1); // PIVNUL_LIST is on the host
      throw SingularMatrixError("MUMPS", equation);
    }
  }

  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override {
    if (rhs.rows() != id_.n) {
      throw LinearSolverError("MUMPS: right-hand side size differs from the matrix size");
    }
    // On several processes the parallel MUMPS 5.5.1 refused the sparse right-hand sides with a
    // centralised solution (INFOG(1) = -22, INFOG(2) = 7, hertz_cylinder under mpirun -n 2): the
    // dense block, the same solution, more work in the forward substitution.
    if (!distributed_ && isSparse(rhs)) {
      solveSparse(rhs);
      return;
    }
    Eigen::MatrixXd b = rhs; // contiguous column-major copy
    id_.rhs = b.data();
    id_.nrhs = static_cast<int>(b.cols());
    id_.lrhs = id_.n;
    id_.job = jobSolve;
    dmumps_c(&id_);
    check("solution");
    checkBackwardError();
    mpi::broadcast(b.data(), b.size()); // the host's solution (ICNTL(21) = 0) to every process
    rhs = b;
  }

private:
  // A block of right-hand sides with under 5 % non-zeros (the columns of A^T in the Schur
  // complement of discrete contact: a few DOFs each) goes to MUMPS as a sparse right-hand side
  // (ICNTL(20) = 1), whose forward substitution then skips the parts of the factor the columns
  // do not reach. The solution comes back dense and is the same.
  static bool isSparse(const Eigen::Ref<Eigen::MatrixXd>& rhs) {
    if (rhs.cols() < 2) {
      return false;
    }
    const auto nonZeros = (rhs.array() != 0.0).count();
    return nonZeros > 0 && 20 * nonZeros < rhs.size();
  }

  void solveSparse(Eigen::Ref<Eigen::MatrixXd> rhs) {
    std::vector<double> values;
    std::vector<MUMPS_INT> rows;
    std::vector<MUMPS_INT> starts; // 1-based, one per column plus the end
    starts.reserve(static_cast<std::size_t>(rhs.cols()) + 1);
    for (Eigen::Index j = 0; j < rhs.cols(); ++j) {
      starts.push_back(static_cast<MUMPS_INT>(values.size()) + 1);
      for (Eigen::Index i = 0; i < rhs.rows(); ++i) {
        if (rhs(i, j) != 0.0) {
          values.push_back(rhs(i, j));
          rows.push_back(static_cast<MUMPS_INT>(i) + 1);
        }
      }
    }
    starts.push_back(static_cast<MUMPS_INT>(values.size()) + 1);
    Eigen::MatrixXd x(rhs.rows(), rhs.cols());
    id_.icntl[19] = 1; // ICNTL(20): sparse right-hand sides, sparsity exploited
    id_.nz_rhs = static_cast<MUMPS_INT>(values.size());
    id_.nrhs = static_cast<MUMPS_INT>(rhs.cols());
    id_.rhs_sparse = values.data();
    id_.irhs_sparse = rows.data();
    id_.irhs_ptr = starts.data();
    id_.rhs = x.data();
    id_.lrhs = id_.n;
    id_.job = jobSolve;
    dmumps_c(&id_);
    id_.icntl[19] = 0;
    id_.rhs_sparse = nullptr;
    id_.irhs_sparse = nullptr;
    id_.irhs_ptr = nullptr;
    check("solution (sparse right-hand sides)");
    mpi::broadcast(x.data(), x.size());
    rhs = x;
  }

  // RESI_RELA > 0: the componentwise backward errors of the solve (ICNTL(11) = 2) must not exceed it.
  void checkBackwardError() const {
    const double limit = options_.mumps.backwardErrorLimit;
    const double error = id_.rinfog[6] + id_.rinfog[7]; // RINFOG(7) + RINFOG(8)
    if (limit > 0.0 && id_.nrhs == 1 && !(error <= limit)) {
      throw LinearSolverError(
          "MUMPS: the backward error of the solution, " + fmtReal(error) + ", exceeds RESI_RELA = " +
          fmtReal(limit) + " (try POSTTRAITEMENTS='FORCE', a smaller LOW_RANK_SEUIL or ACCELERATION='FR')");
    }
  }

  void check(const char* phase) const {
    // -7 and -13: MUMPS could not allocate its workspace (the machine's memory, or the run's P
    // memory_limit): the same out-of-memory error as any other allocation (MEMORY_1).
    if (id_.infog[0] == -7 || id_.infog[0] == -13) {
      throw std::bad_alloc();
    }
    if (id_.infog[0] < 0) {
      throw LinearSolverError(std::string("MUMPS: ") + phase +
                              " failed (INFOG(1) = " + std::to_string(id_.infog[0]) +
                              ", INFOG(2) = " + std::to_string(id_.infog[1]) + ")");
    }
  }

  // ICNTL(18) = 3: this process's share of the entries, a contiguous slice of the pattern (every
  // process holds the whole matrix: the assembly is replicated); `values` null: pattern only.
  void giveLocalEntries(const double* values) {
    const long long total = static_cast<long long>(irn_.size());
    const long long first = total * mpi::rank() / mpi::size();
    const long long last = total * (mpi::rank() + 1) / mpi::size();
    id_.nnz_loc = last - first;
    id_.irn_loc = irn_.data() + first;
    id_.jcn_loc = jcn_.data() + first;
    id_.a_loc = values != nullptr ? const_cast<double*>(values) + first : nullptr;
  }

  SolverOptions options_;
  bool distributed_ = false;
  double busiestFlops_ = 0.0;
  DMUMPS_STRUC_C id_;
  bool initialised_ = false;
  bool factorised_ = false;
  std::vector<MUMPS_INT> irn_, jcn_;
};

} // namespace

std::unique_ptr<LinearSolver> makeMumps(const SolverOptions& o, MatrixKind k) {
  return std::make_unique<MumpsSolver>(o, k);
}

} // namespace stella::linalg::detail
