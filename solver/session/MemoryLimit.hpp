#pragma once
// The memory limit of a run (`P memory_limit <MiB>` of the export), as code_aster's run script
// applies it: a limit on the process's address space while the command files run. An allocation
// beyond it fails, and the command that made it stops with MEMORY_1 (the results computed before
// it are kept); the limit is lifted before the result files are copied back.

namespace stella {

class ScopedMemoryLimit {
public:
  // 0: no limit (nothing is changed).
  explicit ScopedMemoryLimit(double mebibytes);
  ~ScopedMemoryLimit();
  ScopedMemoryLimit(const ScopedMemoryLimit&) = delete;
  ScopedMemoryLimit& operator=(const ScopedMemoryLimit&) = delete;

private:
  bool applied_ = false;
  unsigned long long previous_ = 0;
};

// The limit in force (MiB), 0 when none: named in the MEMORY_1 advice.
double activeMemoryLimit();

} // namespace stella
