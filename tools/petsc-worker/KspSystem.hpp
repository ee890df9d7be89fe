#pragma once
// The PETSc side of SOLVEUR METHODE='PETSC': one sequential AIJ matrix (the upper triangle stella
// sends is mirrored), a KSP (ALGORITHME) with its preconditioner (PRE_COND), the rigid-body
// modes of the node coordinates as the matrix's near-null space (GAMG, ML, BOOMER), and the
// preconditioner kept across matrices when stella asks (REAC_PRECOND, LDLT_SP).

#include "solver/linalg/PetscProtocol.hpp"

#include <petscksp.h>

#include <memory>
#include <string>
#include <vector>

namespace stella::petsc_worker {

struct MatrixMessage {
  std::int64_t size = 0;
  std::int32_t blockSize = 1;
  bool upper = true;        // the CSR holds the upper triangle of a symmetric matrix
  bool samePattern = false; // the pattern of the previous matrix, only the values differ
  bool rebuild = true;      // rebuild the preconditioner (else keep the previous one)
  std::vector<std::int64_t> rowStart;
  std::vector<std::int32_t> columns;
  std::vector<double> values;
  static MatrixMessage receive(petsc_protocol::Channel& c);
};

struct SolveReport {
  bool converged = true;
  int iterations = 0;            // the largest over the right-hand sides
  double relativeResidual = 0.0; // the largest ||b - A x|| / ||b||
  std::string message;
};

// PETSc's message of the last error (the handler keeps the first line of each error chain).
void installErrorHandler();

class SinglePrecisionMumps;

class KspSystem {
public:
  explicit KspSystem(petsc_protocol::Configuration c);
  ~KspSystem();
  KspSystem(const KspSystem&) = delete;
  KspSystem& operator=(const KspSystem&) = delete;

  void setMatrix(const MatrixMessage& m);
  void setCoordinates(int dimension, std::vector<double> coordinates);
  // Solves in place for the `columns` right-hand sides of `rhs` (column-major).
  SolveReport solve(std::vector<double>& rhs, int columns);

private:
  void createMatrix(const MatrixMessage& m);
  void fillValues(const MatrixMessage& m);
  void attachNearNullSpace();
  void configurePreconditioner();

  petsc_protocol::Configuration config_;
  Mat matrix_ = nullptr;
  KSP ksp_ = nullptr;
  PetscInt size_ = 0;
  PetscInt blockSize_ = 1;
  // Where each value of the message goes in the full CSR (and its mirror, -1 on the diagonal).
  std::vector<PetscInt> slot_, mirror_;
  std::vector<double> coordinates_;
  int dimension_ = 0;
  std::unique_ptr<SinglePrecisionMumps> ldltSp_;
};

} // namespace stella::petsc_worker
