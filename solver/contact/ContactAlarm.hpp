#pragma once
// A contact alarm noted during a step, as the "ID: text" line ContactConstraint::reportStep turns
// back into an <A> diagnostic of the session (or writes to the log).

#include "interpreter/Diagnostics.hpp"

#include <string>

namespace stella {

inline std::string alarmLine(const Diagnostic& d) {
  return d.id + ": " + d.message;
}

} // namespace stella
