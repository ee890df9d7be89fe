#pragma once
// The memory limit of a run (`P memory_limit <MiB>` of the export), as code_aster's run script
// applies it: a limit on the process's address space while the command files run. An allocation
// beyond it fails, and the command that made it stops with MEMORY_1 (the results computed before
// it are kept); the limit is lifted before the result files are copied back. The limit counts
// from the address space the process has when it is applied (its libraries, the threads a
// multithreaded BLAS starts at load with their reservations: tens to hundreds of MiB of address
// space that depend on the machine, not on the study), so that the same study gets the same
// headroom on every machine.

namespace stella {

class ScopedMemoryLimit {
public:
  // 0: no limit (nothing is changed).
  explicit ScopedMemoryLimit(double mebibytes);
  ~ScopedMemoryLimit();
  ScopedMemoryLimit(const ScopedMemoryLimit&) = delete;
  ScopedMemoryLimit& operator=(const ScopedMemoryLimit&) = delete;
  // The address space when the limit was applied (MiB), added to the limit.
  double footprint() const { return footprint_; }

private:
  bool applied_ = false;
  unsigned long long previous_ = 0;
  double footprint_ = 0.0;
};

// The limit in force (MiB), 0 when none: named in the MEMORY_1 advice.
double activeMemoryLimit();

} // namespace stella
