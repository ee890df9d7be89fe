#pragma once
// Orderings the factorisation libraries do not provide themselves, given to them as a
// permutation (SOLVEUR RENUM='RCMK' of METHODE='LDLT': CHOLMOD_GIVEN, UMFPACK_ORDERING_GIVEN).

#include "solver/linalg/SparseMatrix.hpp"

#include <vector>

namespace stella::linalg {

// Reverse Cuthill-McKee of the symmetric graph of `p` (Full or Upper storage): order[k] is the
// equation placed k-th. Each connected component starts from a pseudo-peripheral node (the last
// level of repeated breadth-first searches from a node of smallest degree), neighbours are visited
// by increasing degree, and the whole order is reversed.
std::vector<int> reverseCuthillMcKee(const SparsePattern& p);

// The bandwidth max |i - j| of `p` under `order` (order[k] = equation placed k-th).
int bandwidth(const SparsePattern& p, const std::vector<int>& order);

} // namespace stella::linalg
