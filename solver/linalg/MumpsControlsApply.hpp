#pragma once
// Sets MumpsControls (MumpsControls.hpp) on a MUMPS instance, double or single precision, and
// words what MUMPS did (INFOG) for the message file. Included by the MUMPS backends only.

#include "solver/linalg/MumpsControls.hpp"

#include <cstdio>
#include <filesystem>
#include <string>
#include <type_traits>

namespace stella::linalg {

// Megabytes the process may still allocate: MemAvailable, capped by RLIMIT_AS minus the
// address space in use (P memory_limit). Used by GESTION_MEMOIRE='AUTO'.
double availableMegabytes();

std::string fmtReal(double v); // "%.3g"

// Controls read at the analysis (everything but the out-of-core choice of AUTO).
template <class Struc> void applyMumpsControls(Struc& id, const MumpsControls& c) {
  id.icntl[5] = c.preprocessing == "SANS" ? 0 : 7;  // ICNTL(6)
  id.icntl[7] = c.preprocessing == "SANS" ? 0 : 77; // ICNTL(8)
  id.icntl[21] = c.memory == "OUT_OF_CORE" ? 1 : 0; // ICNTL(22)
  if (c.lowRank()) {
    id.icntl[34] = 2;                               // ICNTL(35): BLR factorisation and solve
    id.icntl[35] = 0;                               // ICNTL(36): standard UFSC variant
    id.icntl[36] = c.acceleration == "LR+" ? 1 : 0; // ICNTL(37): compressed contribution blocks
    id.cntl[6] = static_cast<std::remove_reference_t<decltype(id.cntl[6])>>(c.lowRankThreshold); // CNTL(7)
  } else {
    id.icntl[34] = 0;
  }
  if (c.postprocessing == "SANS") {
    id.icntl[9] = 0;
  } else if (c.postprocessing == "MINI") {
    id.icntl[9] = -1;
  } else if (c.postprocessing == "FORCE") {
    id.icntl[9] = 10;
    id.cntl[1] = 0.0; // CNTL(2) = 0: iterate until the backward error stops decreasing
  } else {            // AUTO
    id.icntl[9] = c.backwardErrorLimit > 0.0 || c.lowRank() ? 4 : 0;
  }
  id.icntl[10] = c.backwardErrorLimit > 0.0 ? 2 : 0; // ICNTL(11): backward errors RINFOG(7), (8)
  const std::string dir = std::filesystem::current_path().string();
  std::snprintf(id.ooc_tmpdir, sizeof id.ooc_tmpdir, "%s", dir.c_str());
}

// GESTION_MEMOIRE='AUTO', after the analysis: out of core when the in-core estimate does not fit.
template <class Struc> void chooseMumpsMemory(Struc& id, const MumpsControls& c) {
  if (c.memory != "AUTO") {
    return;
  }
  // INFOG(17): in-core total estimate (MB); INFOG(36): the same with block low-rank factors
  const double estimate = c.lowRank() && id.infog[35] > 0 ? id.infog[35] : id.infog[16];
  id.icntl[21] = estimate > 0.9 * availableMegabytes() ? 1 : 0;
}

// One line of what MUMPS did in the last factorisation (and solve), for the message file; the
// flops are RINFOG(3), or RINFOG(14) (the operations done) with block low-rank.
template <class Struc> std::string mumpsSummary(const Struc& id, const MumpsControls& c) {
  // INFOG(29): entries of the factors; INFOG(35): the same after BLR compression (negative: millions)
  const auto entries = [&](int i) { return id.infog[i] >= 0 ? id.infog[i] : -1e6 * id.infog[i]; };
  std::string s =
      "MUMPS " + std::string(id.icntl[21] == 1 ? "out of core" : "in core") + ", " +
      (id.icntl[34] == 2 ? "block low-rank (CNTL(7) = " + fmtReal(id.cntl[6]) + ")" : "full rank") +
      ", factorisation " + fmtReal(id.icntl[34] == 2 ? id.rinfog[13] : id.rinfog[2]) + " flops, factors " +
      fmtReal(entries(28)) + " entries";
  if (id.icntl[34] == 2) {
    s += " (" + fmtReal(entries(34)) + " after compression)";
  }
  s += ", memory used " + std::to_string(id.infog[21]) + " MB (INFOG(22))";
  if (id.icntl[9] != 0) {
    s += ", refinement steps " + std::to_string(id.infog[14]);
  }
  if (c.backwardErrorLimit > 0.0) {
    s += ", backward error " + fmtReal(id.rinfog[6] + id.rinfog[7]);
  }
  return s;
}

} // namespace stella::linalg
