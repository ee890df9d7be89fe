#pragma once
// Names of the nodes (N1, N2...) or cells (M1, M2...) of a mesh, stored compactly: while every
// name is the default one (prefix + 1-based index) nothing is stored and names are generated on
// demand; names read from a file are kept in one character pool with one offset per entry.
// Lookup by name parses default names directly and otherwise binary-searches an index sorted
// by name, built on first use (4 bytes per entry).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stella {

class NameTable {
public:
  explicit NameTable(char prefix = 'N') : prefix_(prefix) {}

  char prefix() const { return prefix_; }
  std::int32_t size() const { return count_; }
  // True while every name is the default one.
  bool isDefault() const { return offsets_.empty(); }

  // Adds `n` entries with default names (or generated unique names when custom names exist).
  void appendDefault(std::int32_t n);
  // Adds one entry with a given name (switches to stored names when it is not the default one).
  void append(std::string_view name);
  // Keeps only the entries for which keep[i] is true, in order (for cell or node removal).
  void filter(const std::vector<bool>& keep);
  void clear();

  std::string name(std::int32_t index) const;
  std::optional<std::int32_t> find(std::string_view name) const;

  std::size_t memoryBytes() const;

private:
  std::string defaultName(std::int32_t index) const;
  void materialise(); // switch from default to stored names
  std::string_view stored(std::int32_t index) const;

  char prefix_;
  std::int32_t count_ = 0;
  std::string pool_;
  std::vector<std::uint32_t> offsets_;       // count_+1 entries when names are stored
  mutable std::vector<std::int32_t> sorted_; // lazily built lookup index
};

} // namespace stella
