#pragma once
// One error path for the whole run: an exception from the standard library or the OS (file
// system, memory) becomes a located <F> diagnostic with an id, the file path, the OS reason
// (strerror) and advice, instead of escaping to `terminate` (exit 134).
//   RUN_6     a file operation of the run failed (std::filesystem_error, std::system_error)
//   MEMORY_1  not enough memory
//   INTERNAL_2 any other exception: a bug in stella

#include "interpreter/Diagnostics.hpp"

#include <exception>
#include <string>

namespace stella {

// `during` says what the run was doing ("copying the result files back", "running IMPR_RESU").
Diagnostic diagnosticOf(const std::exception& e, const std::string& during, SourceLocation at = {});

// The OS reason of an errno value, e.g. "No space left on device (ENOSPC)".
std::string osReason(int error);
// What to do about it, e.g. "free some space on that file system...".
std::string osAdvice(int error);

} // namespace stella
