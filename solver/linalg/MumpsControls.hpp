#pragma once
// MUMPS's own options as SOLVEUR names them (GESTION_MEMOIRE, ACCELERATION, LOW_RANK_SEUIL,
// PRETRAITEMENTS, POSTTRAITEMENTS, RESI_RELA), set on the double (METHODE='MUMPS') and the
// single-precision (GCPC PRE_COND='LDLT_SP') instances alike, and the one-line summary of what
// MUMPS did (INFOG) written in the message file. The catalogue (SOLVEUR.cata) says which values
// are implemented; the inputs layer reads them into MumpsControls. The functions that set them
// on a MUMPS instance: MumpsControlsApply.hpp (included by the MUMPS backends only).
//
//   GESTION_MEMOIRE  IN_CORE: ICNTL(22) = 0; OUT_OF_CORE: ICNTL(22) = 1, factors written in the
//                    process's current directory; AUTO: in core when the analysis's estimate
//                    (INFOG(17), or INFOG(36) with block low-rank) fits in the memory available
//                    (MemAvailable, and the P memory_limit of the run), out of core otherwise.
//   ACCELERATION     AUTO, FR: full rank, ICNTL(35) = 0; LR: block low-rank factorisation and
//                    solve, ICNTL(35) = 2, CNTL(7) = LOW_RANK_SEUIL; LR+: LR with the
//                    contribution blocks compressed too, ICNTL(37) = 1 (less memory). LR and LR+
//                    are refused by the catalogue for now (MUMPS 5.5.1's BLR clustering crashed
//                    in SCOTCH 7, doc/fem.md): written here, not reachable from a command file.
//   PRETRAITEMENTS   AUTO: MUMPS's permutation and scaling choice (ICNTL(6) = 7, ICNTL(8) = 77);
//                    SANS: neither (ICNTL(6) = 0, ICNTL(8) = 0).
//   POSTTRAITEMENTS  iterative refinement ICNTL(10): SANS 0; MINI exactly one step (-1); FORCE up
//                    to 10 steps until the backward error stops decreasing (CNTL(2) = 0); AUTO up
//                    to 4 steps (CNTL(2) default) when RESI_RELA > 0 or ACCELERATION is LR/LR+,
//                    none otherwise.
//   RESI_RELA > 0    the backward error of every solve (ICNTL(11) = 2: RINFOG(7) + RINFOG(8), the
//                    componentwise backward errors) must not exceed it, else the solve fails.

#include <string>

namespace stella::linalg {

struct MumpsControls {
  std::string memory = "AUTO";         // GESTION_MEMOIRE
  std::string acceleration = "AUTO";   // ACCELERATION
  double lowRankThreshold = 0.0;       // LOW_RANK_SEUIL
  std::string preprocessing = "AUTO";  // PRETRAITEMENTS
  std::string postprocessing = "AUTO"; // POSTTRAITEMENTS
  double backwardErrorLimit = -1.0;    // RESI_RELA (METHODE='MUMPS'); <= 0: not checked

  bool lowRank() const { return acceleration == "LR" || acceleration == "LR+"; }
};

} // namespace stella::linalg
