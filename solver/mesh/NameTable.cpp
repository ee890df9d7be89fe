// Compact node and cell names (see NameTable.hpp).

#include "solver/mesh/NameTable.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>
#include <charconv>

namespace stella {

std::string NameTable::defaultName(std::int32_t index) const {
  return std::string(1, prefix_) + std::to_string(index + 1);
}

void NameTable::materialise() {
  if (!offsets_.empty()) {
    return;
  }
  offsets_.reserve(static_cast<std::size_t>(count_) + 1);
  offsets_.push_back(0);
  for (std::int32_t i = 0; i < count_; ++i) {
    pool_ += defaultName(i);
    offsets_.push_back(static_cast<std::uint32_t>(pool_.size()));
  }
}

std::string_view NameTable::stored(std::int32_t index) const {
  const auto i = static_cast<std::size_t>(index);
  return std::string_view(pool_).substr(offsets_[i], offsets_[i + 1] - offsets_[i]);
}

void NameTable::appendDefault(std::int32_t n) {
  if (isDefault()) {
    count_ += n;
    sorted_.clear();
    return;
  }
  for (std::int32_t k = 0; k < n; ++k) {
    std::string candidate = defaultName(count_);
    for (int suffix = 1; find(candidate).has_value(); ++suffix) {
      candidate = defaultName(count_) + "_" + std::to_string(suffix);
    }
    append(candidate);
  }
}

void NameTable::append(std::string_view name) {
  if (isDefault() && name == defaultName(count_)) {
    ++count_;
    sorted_.clear();
    return;
  }
  materialise();
  pool_.append(name);
  STELLA_ASSERT(pool_.size() < 0xffffffffu, "name pool overflow");
  offsets_.push_back(static_cast<std::uint32_t>(pool_.size()));
  ++count_;
  sorted_.clear();
}

void NameTable::filter(const std::vector<bool>& keep) {
  STELLA_ASSERT(static_cast<std::int32_t>(keep.size()) == count_, "filter size");
  if (isDefault()) {
    // Default names stay default: renumbering is what code_aster does for generated names.
    count_ = static_cast<std::int32_t>(std::count(keep.begin(), keep.end(), true));
    sorted_.clear();
    return;
  }
  NameTable kept(prefix_);
  for (std::int32_t i = 0; i < count_; ++i) {
    if (keep[static_cast<std::size_t>(i)]) {
      kept.append(stored(i));
    }
  }
  *this = std::move(kept);
}

void NameTable::clear() {
  count_ = 0;
  pool_.clear();
  offsets_.clear();
  sorted_.clear();
}

std::string NameTable::name(std::int32_t index) const {
  STELLA_ASSERT(index >= 0 && index < count_, "name index out of range");
  if (isDefault()) {
    return defaultName(index);
  }
  return std::string(stored(index));
}

std::optional<std::int32_t> NameTable::find(std::string_view name) const {
  if (isDefault()) {
    if (name.size() < 2 || name[0] != prefix_ || name[1] == '0') {
      return std::nullopt;
    }
    std::int64_t value = 0;
    const auto* end = name.data() + name.size();
    const auto [ptr, ec] = std::from_chars(name.data() + 1, end, value);
    if (ec != std::errc() || ptr != end || value < 1 || value > count_) {
      return std::nullopt;
    }
    return static_cast<std::int32_t>(value - 1);
  }
  if (static_cast<std::int32_t>(sorted_.size()) != count_) {
    sorted_.resize(static_cast<std::size_t>(count_));
    for (std::int32_t i = 0; i < count_; ++i) {
      sorted_[static_cast<std::size_t>(i)] = i;
    }
    std::stable_sort(sorted_.begin(), sorted_.end(),
                     [this](std::int32_t a, std::int32_t b) { return stored(a) < stored(b); });
  }
  const auto it = std::lower_bound(sorted_.begin(), sorted_.end(), name,
                                   [this](std::int32_t a, std::string_view n) { return stored(a) < n; });
  if (it != sorted_.end() && stored(*it) == name) {
    return *it;
  }
  return std::nullopt;
}

std::size_t NameTable::memoryBytes() const {
  return sizeof(*this) + pool_.capacity() + offsets_.capacity() * sizeof(std::uint32_t) +
         sorted_.capacity() * sizeof(std::int32_t);
}

} // namespace stella
