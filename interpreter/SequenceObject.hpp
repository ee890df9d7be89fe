#pragma once
// A native object that reads like a Python sequence: `obj[i]` (negative indices from the end)
// and `len(obj)`, e.g. the coordinates field a mesh's getCoordinates() returns.

#include "Value.hpp"

#include <cstdint>

namespace stella {

class SequenceObject : public NativeObject {
public:
  virtual std::int64_t length() const = 0;
  // The item at 0 <= index < length() (the caller checks the range).
  virtual Value item(std::int64_t index) const = 0;
};

} // namespace stella
