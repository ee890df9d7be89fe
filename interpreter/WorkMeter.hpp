#pragma once
// The evaluation budget of a command file, counted in work rather than in loop turns: the
// operations evaluated (statements, loop turns, expressions, items visited by built-ins) and the
// memory the language's values make the process grow by (its resident size, less what the
// commands called meanwhile added). A budget exceeded is the LangError LANG_BUDGET; the
// evaluator locates it and names the loop that was running.

#include <cstdint>
#include <string>

namespace stella {

struct EvaluationBudget {
  static constexpr std::int64_t defaultOperations = 1'000'000'000;
  static constexpr std::int64_t defaultMemoryBytes = std::int64_t{2} << 30; // 2 GiB
  std::int64_t operations = defaultOperations;                              // 0: unlimited
  std::int64_t memoryBytes = 0; // 0: the default (2 GiB, at most half the RAM)
};

class WorkMeter {
public:
  explicit WorkMeter(const EvaluationBudget& budget);

  // One operation; every `memoryCheckInterval` operations the memory is measured.
  void operation() {
    if (++operations_ > operationLimit_) {
      operationsExceeded();
    }
    if ((operations_ & (memoryCheckInterval - 1)) == 0) {
      checkMemory(0);
    }
  }
  // `n` operations at once (a built-in copying n items)
  void operations(std::int64_t n) {
    operations_ += n;
    if (operations_ > operationLimit_) {
      operationsExceeded();
    }
  }
  // `bytes` about to be held by a language value (a list, a string): measured at once when
  // enough has been allocated since the last measure.
  void allocation(std::int64_t bytes) {
    pending_ += bytes;
    if (pending_ >= allocationCheckBytes) {
      checkMemory(bytes);
    }
  }
  // Commands (the solver) own the memory they allocate: it is excluded from the language's.
  void enterCommand();
  void leaveCommand();

  std::int64_t operations() const { return operations_; }
  std::int64_t operationLimit() const { return operationLimit_; }
  std::int64_t memoryLimit() const { return memoryLimit_; }
  // The memory the language's values hold now (bytes), as measured.
  std::int64_t languageMemory() const;

  static constexpr std::int64_t memoryCheckInterval = 1 << 16;
  static constexpr std::int64_t allocationCheckBytes = 16 << 20;

private:
  [[noreturn]] void operationsExceeded() const;
  void checkMemory(std::int64_t upcoming);

  std::int64_t operations_ = 0;
  std::int64_t operationLimit_;
  std::int64_t memoryLimit_;
  std::int64_t pending_ = 0;
  std::int64_t baseline_;          // resident size at the start, plus what commands added
  std::int64_t commandStart_ = -1; // resident size when the current command started
  int commandDepth_ = 0;
};

// The meter of the evaluation running on this thread (nullptr outside one): the built-ins that
// visit many items and the operations that build large values charge it.
WorkMeter* activeWorkMeter();
void setActiveWorkMeter(WorkMeter* meter);
inline void chargeOperation() {
  if (WorkMeter* m = activeWorkMeter()) {
    m->operation();
  }
}
inline void chargeAllocation(std::int64_t bytes) {
  if (WorkMeter* m = activeWorkMeter()) {
    m->allocation(bytes);
  }
}
// A built-in about to make `items` values of `itemBytes` each: as many operations, and memory.
inline void chargeBulk(std::int64_t items, std::int64_t itemBytes) {
  if (WorkMeter* m = activeWorkMeter()) {
    m->operations(items);
    m->allocation(items * itemBytes);
  }
}

// The process's resident size in bytes (Linux /proc/self/statm), 0 when unknown.
std::int64_t residentBytes();
// "2 GiB", "512 MiB"
std::string formatBytes(std::int64_t bytes);

} // namespace stella
