#pragma once
// The MPI world of a run (issue 21, doc/parallel.md). A build with STELLA_MPI links OpenMPI and the
// parallel MUMPS; every process of `mpirun -n N stella run ...` runs the whole study (the mesh,
// the command files, the assembly are replicated) and the MUMPS factorisations and solves are
// shared by the N processes. Rank 0 alone writes the message file and the result files.
//
// MPI is initialised once, before the first MUMPS call (or at the start of the run under mpirun):
// a serial run is a world of one process. Without STELLA_MPI every function here describes that
// world of one and does nothing. Free of mpi.h: the MED headers must not meet it (MedCommon.hpp).

#include <string>
#include <vector>

namespace stella::mpi {

// Whether this stella links MPI (STELLA_MPI): false for the sequential build.
bool built();
// Whether this process was started by mpirun/mpiexec (its environment says so).
bool underLauncher();
// Initialises MPI when this build has it and it is not yet (MPI_Init_thread, funneled); a process
// not started by mpirun is a singleton world without a daemon. Idempotent; returns the seconds
// MPI_Init_thread took (0 when it was already done or there is no MPI).
double initialise();
// MPI_Finalize when initialise() initialised MPI (at the end of the process).
void finalise();
int rank(); // 0 before initialise() under no launcher
int size(); // 1 likewise
// The environment's view before MPI_Init: the world size mpirun announced (1 without it).
int launchedSize();
int launchedRank();
// The Fortran handle of the world (MUMPS's COMM), or MUMPS's code of the sequential library's
// world when there is no MPI. Initialises MPI.
int fortranWorld();
// The Fortran handle of MPI_COMM_SELF: a MUMPS instance private to this process (GCPC's LDLT_SP).
int fortranSelf();
// What the message file's header says after "MPI processes: N": how the work is shared.
std::string partitioningNote();
// Rank 0's values to every rank (a no-op in a world of one).
void broadcast(double* values, long long count);
void broadcast(int* values, long long count);
// The largest of the ranks' values (a collective call).
double maxOver(double value);
// The element-wise sum over the ranks, in place.
void sumInPlace(double* values, long long count);
// Ends every process of the world with `code` (MPI_Abort), after this process's `message` went
// to the standard error; in a world of one, std::_Exit(code).
[[noreturn]] void abortAll(int code, const std::string& message);
// The fault injection of the test mpi.failure-one-rank: when the environment variable
// STELLA_MPI_FAIL_RANK names this process's rank (a world of more than one), throws
// std::runtime_error naming `where`, as a failure of that process alone would.
void failIfInjected(const char* where);
// At the end of a run: every rank gives its exit code and gets the largest. A rank that arrives
// when another never will (it failed alone and stopped, or hangs in a collective) is ended with
// every other by MPI_Abort after `patienceSeconds`, with `message` on its standard error.
int agreeOnExitCode(int code, double patienceSeconds, const std::string& message);

} // namespace stella::mpi
