// PRE_COND='LDLT_SP' of METHODE='PETSC' (SinglePrecisionMumps.hpp).

#include "SinglePrecisionMumps.hpp"

#include "solver/linalg/MumpsFactorise.hpp"

#include <stdexcept>
#include <string>

namespace stella::petsc_worker {
namespace {
constexpr int jobInit = -1, jobEnd = -2, jobAnalyse = 1, jobSolve = 3;
}

SinglePrecisionMumps::SinglePrecisionMumps(int pivotPercent, int ordering) {
  id_.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(PETSC_COMM_SELF));
  id_.par = 1;
  id_.sym = 1; // symmetric positive definite: LL^T without pivoting
  id_.job = jobInit;
  smumps_c(&id_);
  check("initialisation");
  id_.icntl[0] = id_.icntl[1] = id_.icntl[2] = -1;
  id_.icntl[3] = 0;
  id_.icntl[6] = ordering;      // ICNTL(7)
  id_.icntl[13] = pivotPercent; // ICNTL(14) = PCENT_PIVOT
}

SinglePrecisionMumps::~SinglePrecisionMumps() {
  id_.job = jobEnd;
  smumps_c(&id_);
}

void SinglePrecisionMumps::install(PC pc) {
  if (PCSetType(pc, PCSHELL) != 0 || PCShellSetContext(pc, this) != 0 || PCShellSetSetUp(pc, setUp) != 0 ||
      PCShellSetApply(pc, apply) != 0 || PCShellSetName(pc, "LDLT_SP (single-precision MUMPS)") != 0) {
    throw std::runtime_error("LDLT_SP: the PCSHELL could not be set up");
  }
}

void SinglePrecisionMumps::check(const char* phase) const {
  if (id_.infog[0] < 0) {
    throw std::runtime_error(std::string("LDLT_SP: MUMPS ") + phase +
                             " failed (INFOG(1) = " + std::to_string(id_.infog[0]) + ")");
  }
}

void SinglePrecisionMumps::factorise(Mat a) {
  PetscInt n = 0;
  const PetscInt *ia = nullptr, *ja = nullptr;
  PetscBool done = PETSC_FALSE;
  const PetscScalar* values = nullptr;
  if (MatGetRowIJ(a, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done) != 0 || !done ||
      MatSeqAIJGetArrayRead(a, &values) != 0) {
    throw std::runtime_error("LDLT_SP: the matrix's rows could not be read");
  }
  if (!analysed_) {
    irn_.clear();
    jcn_.clear();
    slots_.clear();
    for (PetscInt i = 0; i < n; ++i) {
      for (PetscInt s = ia[i]; s < ia[i + 1]; ++s) {
        if (ja[s] >= i) {
          irn_.push_back(static_cast<MUMPS_INT>(i + 1));
          jcn_.push_back(static_cast<MUMPS_INT>(ja[s] + 1));
          slots_.push_back(s);
        }
      }
    }
    id_.n = static_cast<MUMPS_INT>(n);
    id_.nnz = static_cast<int64_t>(irn_.size());
    id_.irn = irn_.data();
    id_.jcn = jcn_.data();
    id_.a = nullptr;
    id_.job = jobAnalyse;
    smumps_c(&id_);
    check("analysis");
    analysed_ = true;
  }
  values_.resize(slots_.size());
  for (std::size_t e = 0; e < slots_.size(); ++e) {
    values_[e] = static_cast<float>(values[slots_[e]]);
  }
  MatSeqAIJRestoreArrayRead(a, &values);
  MatRestoreRowIJ(a, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done);
  id_.a = values_.data();
  linalg::factoriseWithWorkspaceRetries(id_, smumps_c); // more workspace, as stella's MUMPS
  check("factorisation");
}

PetscErrorCode SinglePrecisionMumps::setUp(PC pc) {
  void* context = nullptr;
  Mat a = nullptr;
  if (PCShellGetContext(pc, &context) != 0 || PCGetOperators(pc, nullptr, &a) != 0) {
    return PETSC_ERR_LIB;
  }
  try {
    static_cast<SinglePrecisionMumps*>(context)->factorise(a);
  } catch (const std::exception& e) {
    return PetscError(PETSC_COMM_SELF, __LINE__, "LDLT_SP", __FILE__, PETSC_ERR_LIB, PETSC_ERROR_INITIAL,
                      "%s", e.what());
  }
  return 0;
}

// y = M^-1 x through the single-precision factors.
PetscErrorCode SinglePrecisionMumps::apply(PC pc, Vec x, Vec y) {
  void* context = nullptr;
  if (PCShellGetContext(pc, &context) != 0) {
    return PETSC_ERR_LIB;
  }
  auto* self = static_cast<SinglePrecisionMumps*>(context);
  const PetscScalar* in = nullptr;
  PetscScalar* out = nullptr;
  PetscInt n = 0;
  VecGetLocalSize(x, &n);
  self->work_.resize(static_cast<std::size_t>(n));
  VecGetArrayRead(x, &in);
  for (PetscInt i = 0; i < n; ++i) {
    self->work_[static_cast<std::size_t>(i)] = static_cast<float>(in[i]);
  }
  VecRestoreArrayRead(x, &in);
  self->id_.rhs = self->work_.data();
  self->id_.nrhs = 1;
  self->id_.lrhs = static_cast<MUMPS_INT>(n);
  self->id_.job = jobSolve;
  smumps_c(&self->id_);
  if (self->id_.infog[0] < 0) {
    return PetscError(PETSC_COMM_SELF, __LINE__, "LDLT_SP", __FILE__, PETSC_ERR_LIB, PETSC_ERROR_INITIAL,
                      "MUMPS solve failed (INFOG(1) = %d)", static_cast<int>(self->id_.infog[0]));
  }
  VecGetArray(y, &out);
  for (PetscInt i = 0; i < n; ++i) {
    out[i] = static_cast<PetscScalar>(self->work_[static_cast<std::size_t>(i)]);
  }
  VecRestoreArray(y, &out);
  return 0;
}

} // namespace stella::petsc_worker
