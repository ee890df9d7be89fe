#pragma once
// The factorisation (JOB=2) of a MUMPS instance, double or single precision, with the workspace
// retries of every MUMPS backend (MumpsSolver, SinglePrecisionPcg, the PETSc worker's
// SinglePrecisionMumps). Header only, no dependency: the PETSc worker includes it too.

#include <algorithm>

namespace stella::linalg {

// Runs JOB=2 through `call` (dmumps_c or smumps_c on `id`); while MUMPS reports too little
// workspace (INFOG(1) = -8, -9, -11, -12, -14, -15), relaxes the memory estimate ICNTL(14) (doubled,
// at least 50 %) and retries, at most 4 times. INFOG(1) is left for the caller to check.
template <class Struc, class Call> void factoriseWithWorkspaceRetries(Struc& id, Call call) {
  constexpr int jobFactorise = 2;
  for (int attempt = 0;; ++attempt) {
    id.job = jobFactorise;
    call(&id);
    const int info = id.infog[0];
    if ((info == -8 || info == -9 || info == -11 || info == -12 || info == -14 || info == -15) &&
        attempt < 4) {
      id.icntl[13] = std::max(2 * id.icntl[13], 50);
      continue;
    }
    break;
  }
}

} // namespace stella::linalg
