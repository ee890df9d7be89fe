#pragma once
// `P mpi_nbcpu N` in the .export of a stella started without mpirun: stella starts itself again
// under mpirun with N processes, as code_aster's run tool does (doc/parallel.md).

#include <string>
#include <vector>

namespace stella::mpi {

// The command line that runs `arguments` (argv of this process, argv[0] first) on `processes`
// MPI processes: mpirun -n N [--allow-run-as-root] [--oversubscribe] <this executable> args...
std::vector<std::string> launcherCommand(int processes, const std::vector<std::string>& arguments);

// Replaces this process with launcherCommand(processes, arguments); returns only when that
// failed, with the reason.
std::string relaunchUnderMpirun(int processes, const std::vector<std::string>& arguments);

} // namespace stella::mpi
