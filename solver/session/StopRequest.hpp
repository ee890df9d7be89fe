#pragma once
// A request to stop the run cleanly, checked at safe points (before each command, at the end of
// each converged step of STAT_NON_LINE): SIGINT and SIGTERM set it (a second signal stops the
// process at once), and so does the time limit of the export (`P time_limit`, through SIGALRM).
// The operator that sees it stores what converged and throws a diagnostic of kind Interrupted;
// the run then writes what it kept and copies the results back like after any error.
//
// Under a parent that ignores SIGINT (a background job of a non-interactive shell, nohup),
// SIGINT stays ignored, as POSIX programs do; SIGTERM still stops the run cleanly.

#include "interpreter/Diagnostics.hpp"

#include <string>

namespace stella {

enum class StopReason { None, Signal, TimeLimit };

// Installs the handlers of SIGINT, SIGTERM and SIGALRM (once per process).
void installStopHandlers();
// Arms the time limit: a stop is requested after `seconds` of elapsed time (0: disarms it).
void armTimeLimit(unsigned seconds);

StopReason stopReason();
int stopSignal(); // the signal that asked for the stop (SIGINT, SIGTERM), 0 otherwise
bool stopRequested();
// "signal 15 (SIGTERM)" or "the time limit of 60 s (P time_limit)".
std::string stopCause();
// Forgets a request (tests, and a new run in the same process).
void clearStopRequest();

// The diagnostic of a stop seen at a safe point: kind Interrupted, `where` says what was kept.
Diagnostic stopDiagnostic(const std::string& where, SourceLocation at);

} // namespace stella
