#pragma once
// Which orderings (SOLVEUR RENUM) this build's MUMPS has (MumpsSolver.cpp).

#include <string_view>

namespace stella::linalg {

// Debian's parallel MUMPS (STELLA_MPI) is built without SCOTCH: asked for it, MUMPS would
// silently take another ordering (INFOG(7)), so RENUM='SCOTCH' is refused there.
bool mumpsOrderingAvailable(std::string_view renum);

} // namespace stella::linalg
