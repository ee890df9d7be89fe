#pragma once
// PRE_COND='LDLT_SP' of METHODE='PETSC': a single-precision MUMPS factorisation (SMUMPS, LL^T of
// the upper triangle, SYM=1) of the operator as the KSP's preconditioner (a PCSHELL), the
// parallel MUMPS on one process. Rebuilt at the KSP's PCSetUp, i.e. only when stella asks for
// it (REAC_PRECOND); analysed again when the pattern changed.

#include <petscksp.h>

#include <smumps_c.h>

#include <vector>

namespace stella::petsc_worker {

class SinglePrecisionMumps {
public:
  SinglePrecisionMumps(int pivotPercent, int ordering);
  ~SinglePrecisionMumps();
  SinglePrecisionMumps(const SinglePrecisionMumps&) = delete;
  SinglePrecisionMumps& operator=(const SinglePrecisionMumps&) = delete;

  void install(PC pc);
  void patternChanged() { analysed_ = false; }

private:
  static PetscErrorCode setUp(PC pc);
  static PetscErrorCode apply(PC pc, Vec x, Vec y);
  void factorise(Mat a);
  void check(const char* phase) const;

  SMUMPS_STRUC_C id_{};
  bool analysed_ = false;
  std::vector<MUMPS_INT> irn_, jcn_;
  std::vector<PetscInt> slots_; // the AIJ slot of each upper-triangle entry
  std::vector<float> values_, work_;
};

} // namespace stella::petsc_worker
