#pragma once
// NEWTON/MATR_RIGI_SYME='OUI': the tangent replaced by its symmetric part (K + K^T) / 2, so that
// an unsymmetric tangent (Coulomb friction) is factorised as a symmetric matrix (half the
// storage, an LDL^T factorisation). Newton then converges to the same solution (the residual is
// unchanged), possibly in more iterations.

#include "solver/assembly/StiffnessMatrix.hpp"

namespace stella {

// Fills `upper` (upper storage, same size, zeroed by the caller) with the symmetric part of
// `full` and returns it.
StiffnessMatrix& symmetricPart(const StiffnessMatrix& full, StiffnessMatrix& upper);

} // namespace stella
