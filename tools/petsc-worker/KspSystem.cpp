// The PETSc side of SOLVEUR METHODE='PETSC' (KspSystem.hpp).

#include "KspSystem.hpp"
#include "SinglePrecisionMumps.hpp"

#include <cmath>
#include <stdexcept>

namespace stella::petsc_worker {
namespace {

std::string lastError;

PetscErrorCode keepMessage(MPI_Comm, int line, const char* function, const char* file, PetscErrorCode n,
                           PetscErrorType p, const char* message, void*) {
  if (p == PETSC_ERROR_INITIAL) {
    const char* text = nullptr;
    PetscErrorMessage(n, &text, nullptr);
    lastError = std::string(text ? text : "PETSc error") +
                (message && *message ? std::string(": ") + message : "") + " (" + function + ", " + file +
                ":" + std::to_string(line) + ")";
  }
  return n;
}

void check(PetscErrorCode e, const char* what) {
  if (e != 0) {
    throw std::runtime_error(std::string(what) + ": " + lastError);
  }
}

KSPType kspType(const std::string& algorithm) {
  if (algorithm == "CG") {
    return KSPCG;
  }
  if (algorithm == "GMRES") {
    return KSPGMRES;
  }
  if (algorithm == "GCR") {
    return KSPGCR;
  }
  if (algorithm == "FGMRES") {
    return KSPFGMRES;
  }
  throw std::runtime_error("ALGORITHME='" + algorithm + "' is not available");
}

} // namespace

void installErrorHandler() {
  PetscPushErrorHandler(keepMessage, nullptr);
}

MatrixMessage MatrixMessage::receive(petsc_protocol::Channel& c) {
  MatrixMessage m;
  m.size = c.get<std::int64_t>();
  m.blockSize = c.get<std::int32_t>();
  m.upper = c.get<std::int32_t>() != 0;
  m.samePattern = c.get<std::int32_t>() != 0;
  m.rebuild = c.get<std::int32_t>() != 0;
  if (!m.samePattern) {
    m.rowStart = c.getArray<std::int64_t>();
    m.columns = c.getArray<std::int32_t>();
  }
  m.values = c.getArray<double>();
  return m;
}

KspSystem::KspSystem(petsc_protocol::Configuration c) : config_(std::move(c)) {
  check(KSPCreate(PETSC_COMM_SELF, &ksp_), "KSPCreate");
  check(KSPSetType(ksp_, kspType(config_.algorithm)), "KSPSetType");
  // RESI_RELA bounds the true residual ||b - A x|| / ||b|| whatever the algorithm: CG with a
  // left preconditioner monitors the unpreconditioned norm, GMRES is preconditioned on the right
  // (FGMRES and GCR only are).
  if (config_.algorithm == "CG") {
    check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  } else {
    check(KSPSetPCSide(ksp_, PC_RIGHT), "KSPSetPCSide");
  }
  check(KSPSetTolerances(ksp_, config_.relativeResidual, PETSC_DEFAULT, PETSC_DEFAULT,
                         config_.maxIterations > 0 ? config_.maxIterations : PETSC_DEFAULT),
        "KSPSetTolerances");
  configurePreconditioner();
  if (!config_.options.empty()) {
    check(PetscOptionsInsertString(nullptr, config_.options.c_str()), "OPTION_PETSC");
  }
  check(KSPSetFromOptions(ksp_), "KSPSetFromOptions");
}

KspSystem::~KspSystem() {
  KSPDestroy(&ksp_);
  MatDestroy(&matrix_);
}

void KspSystem::configurePreconditioner() {
  PC pc = nullptr;
  check(KSPGetPC(ksp_, &pc), "KSPGetPC");
  const std::string& p = config_.preconditioner;
  if (p == "GAMG") {
    check(PCSetType(pc, PCGAMG), "PCSetType");
  } else if (p == "BOOMER") {
    check(PCSetType(pc, PCHYPRE), "PCSetType");
    check(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
  } else if (p == "ML") {
    check(PCSetType(pc, PCML), "PCSetType");
  } else if (p == "JACOBI") {
    check(PCSetType(pc, PCJACOBI), "PCSetType");
  } else if (p == "SOR") {
    check(PCSetType(pc, PCSOR), "PCSetType"); // symmetric SOR sweeps: SPD for CG
  } else if (p == "SANS") {
    check(PCSetType(pc, PCNONE), "PCSetType");
  } else if (p == "LDLT_INC") {
    check(PCSetType(pc, PCICC), "PCSetType");
    check(PCFactorSetLevels(pc, config_.fillLevel), "PCFactorSetLevels");
    check(PCFactorSetFill(pc, config_.fill), "PCFactorSetFill");
    check(PCFactorSetMatOrderingType(pc, MATORDERINGRCM), "PCFactorSetMatOrderingType");
  } else if (p == "LDLT_SP") {
    ldltSp_ = std::make_unique<SinglePrecisionMumps>(config_.pivotPercent, config_.mumpsOrdering);
    ldltSp_->install(pc);
  } else {
    throw std::runtime_error("PRE_COND='" + p + "' is not available");
  }
}

void KspSystem::setMatrix(const MatrixMessage& m) {
  if (!m.samePattern || !matrix_) {
    createMatrix(m);
  } else if (!m.values.empty()) {
    fillValues(m);
  }
  if (m.rebuild && m.samePattern && m.values.empty()) { // unchanged values: PCSetUp would keep the PC
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "KSPGetPC");
    check(PCReset(pc), "PCReset");
  }
  check(KSPSetOperators(ksp_, matrix_, matrix_), "KSPSetOperators");
  check(KSPSetReusePreconditioner(ksp_, m.rebuild ? PETSC_FALSE : PETSC_TRUE), "KSPSetReusePreconditioner");
}

void KspSystem::createMatrix(const MatrixMessage& m) {
  const auto n = static_cast<PetscInt>(m.size);
  if (static_cast<std::int64_t>(m.rowStart.size()) != m.size + 1 || m.values.size() != m.columns.size()) {
    throw std::runtime_error("inconsistent matrix message");
  }
  // Row lengths of the full matrix, then each value's slot (and its mirror's): row i gets the
  // mirrored entries of the rows above it first (columns < i, in increasing order), then its own.
  std::vector<PetscInt> start(static_cast<std::size_t>(n) + 1, 0);
  for (PetscInt i = 0; i < n; ++i) {
    for (std::int64_t e = m.rowStart[static_cast<std::size_t>(i)];
         e < m.rowStart[static_cast<std::size_t>(i) + 1]; ++e) {
      const PetscInt j = m.columns[static_cast<std::size_t>(e)];
      ++start[static_cast<std::size_t>(i) + 1];
      if (m.upper && j != i) {
        ++start[static_cast<std::size_t>(j) + 1];
      }
    }
  }
  for (PetscInt i = 0; i < n; ++i) {
    start[static_cast<std::size_t>(i) + 1] += start[static_cast<std::size_t>(i)];
  }
  std::vector<PetscInt> next(start.begin(), start.end() - 1);
  std::vector<PetscInt> columns(static_cast<std::size_t>(start.back()));
  slot_.assign(m.values.size(), 0);
  mirror_.assign(m.values.size(), -1);
  for (PetscInt i = 0; i < n; ++i) {
    for (std::int64_t e = m.rowStart[static_cast<std::size_t>(i)];
         e < m.rowStart[static_cast<std::size_t>(i) + 1]; ++e) {
      const PetscInt j = m.columns[static_cast<std::size_t>(e)];
      const PetscInt s = next[static_cast<std::size_t>(i)]++;
      columns[static_cast<std::size_t>(s)] = j;
      slot_[static_cast<std::size_t>(e)] = s;
      if (m.upper && j != i) {
        const PetscInt t = next[static_cast<std::size_t>(j)]++;
        columns[static_cast<std::size_t>(t)] = i;
        mirror_[static_cast<std::size_t>(e)] = t;
      }
    }
  }
  std::vector<double> values(columns.size());
  for (std::size_t e = 0; e < m.values.size(); ++e) {
    values[static_cast<std::size_t>(slot_[e])] = m.values[e];
    if (mirror_[e] >= 0) {
      values[static_cast<std::size_t>(mirror_[e])] = m.values[e];
    }
  }
  MatDestroy(&matrix_);
  size_ = n;
  blockSize_ = m.blockSize > 1 && n % m.blockSize == 0 ? m.blockSize : 1;
  check(MatCreate(PETSC_COMM_SELF, &matrix_), "MatCreate");
  check(MatSetSizes(matrix_, n, n, n, n), "MatSetSizes");
  check(MatSetType(matrix_, MATSEQAIJ), "MatSetType");
  check(MatSetBlockSize(matrix_, blockSize_), "MatSetBlockSize");
  check(MatSeqAIJSetPreallocationCSR(matrix_, start.data(), columns.data(), values.data()),
        "MatSeqAIJSetPreallocationCSR");
  if (m.upper) {
    check(MatSetOption(matrix_, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption");
    check(MatSetOption(matrix_, MAT_SYMMETRY_ETERNAL, PETSC_TRUE), "MatSetOption");
  }
  attachNearNullSpace();
  if (ldltSp_) {
    ldltSp_->patternChanged();
  }
}

void KspSystem::fillValues(const MatrixMessage& m) {
  if (m.values.size() != slot_.size()) {
    throw std::runtime_error("matrix values of another pattern");
  }
  PetscScalar* a = nullptr;
  check(MatSeqAIJGetArray(matrix_, &a), "MatSeqAIJGetArray");
  for (std::size_t e = 0; e < m.values.size(); ++e) {
    a[slot_[e]] = m.values[e];
    if (mirror_[e] >= 0) {
      a[mirror_[e]] = m.values[e];
    }
  }
  check(MatSeqAIJRestoreArray(matrix_, &a), "MatSeqAIJRestoreArray");
}

void KspSystem::setCoordinates(int dimension, std::vector<double> coordinates) {
  dimension_ = dimension;
  coordinates_ = std::move(coordinates);
  if (matrix_) {
    attachNearNullSpace();
  }
}

// The rigid-body modes of the node coordinates (3 in 2D, 6 in 3D), when the matrix's equations
// are the nodes' components in blocks (no Lagrange multiplier rows).
void KspSystem::attachNearNullSpace() {
  if (dimension_ < 2 || dimension_ != blockSize_ || static_cast<PetscInt>(coordinates_.size()) != size_) {
    return;
  }
  Vec coordinates = nullptr;
  check(VecCreateSeq(PETSC_COMM_SELF, size_, &coordinates), "VecCreateSeq");
  check(VecSetBlockSize(coordinates, dimension_), "VecSetBlockSize");
  PetscScalar* c = nullptr;
  check(VecGetArray(coordinates, &c), "VecGetArray");
  std::copy(coordinates_.begin(), coordinates_.end(), c);
  check(VecRestoreArray(coordinates, &c), "VecRestoreArray");
  MatNullSpace modes = nullptr;
  check(MatNullSpaceCreateRigidBody(coordinates, &modes), "MatNullSpaceCreateRigidBody");
  check(MatSetNearNullSpace(matrix_, modes), "MatSetNearNullSpace");
  MatNullSpaceDestroy(&modes);
  VecDestroy(&coordinates);
}

SolveReport KspSystem::solve(std::vector<double>& rhs, int columns) {
  if (!matrix_ || static_cast<std::int64_t>(rhs.size()) != static_cast<std::int64_t>(size_) * columns) {
    throw std::runtime_error("solve before the matrix, or of the wrong size");
  }
  SolveReport report;
  Vec b = nullptr, x = nullptr, r = nullptr;
  check(MatCreateVecs(matrix_, &x, &b), "MatCreateVecs");
  check(VecDuplicate(b, &r), "VecDuplicate");
  for (int k = 0; k < columns && report.converged; ++k) {
    double* column = rhs.data() + static_cast<std::size_t>(k) * static_cast<std::size_t>(size_);
    PetscScalar* p = nullptr;
    check(VecGetArray(b, &p), "VecGetArray");
    std::copy(column, column + size_, p);
    check(VecRestoreArray(b, &p), "VecRestoreArray");
    PetscReal bNorm = 0.0;
    check(VecNorm(b, NORM_2, &bNorm), "VecNorm");
    if (bNorm == 0.0) {
      std::fill(column, column + size_, 0.0);
      continue;
    }
    check(KSPSolve(ksp_, b, x), "KSPSolve");
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    PetscInt iterations = 0;
    check(KSPGetConvergedReason(ksp_, &reason), "KSPGetConvergedReason");
    check(KSPGetIterationNumber(ksp_, &iterations), "KSPGetIterationNumber");
    check(MatMult(matrix_, x, r), "MatMult");
    check(VecAYPX(r, -1.0, b), "VecAYPX");
    PetscReal rNorm = 0.0;
    check(VecNorm(r, NORM_2, &rNorm), "VecNorm");
    report.iterations = std::max(report.iterations, static_cast<int>(iterations));
    report.relativeResidual = std::max(report.relativeResidual, static_cast<double>(rNorm / bNorm));
    if (reason < 0) {
      report.converged = false;
      report.message = KSPConvergedReasons[reason];
      break;
    }
    const PetscScalar* q = nullptr;
    check(VecGetArrayRead(x, &q), "VecGetArrayRead");
    std::copy(q, q + size_, column);
    check(VecRestoreArrayRead(x, &q), "VecRestoreArrayRead");
  }
  VecDestroy(&b);
  VecDestroy(&x);
  VecDestroy(&r);
  return report;
}

} // namespace stella::petsc_worker
