#pragma once
// The numeric P lines of an export that set limits of the run: each is one number in a range,
// refused with its own id, what it expects and an example otherwise.

#include "Export.hpp"

namespace stella {

// P time_limit <seconds> (EXPORT_9): the run stops at the next safe point once it has run that
// long; 0 when absent.
unsigned timeLimitOf(const Export& study);

// P memory_limit <MiB> (EXPORT_11): the address space the run may use, as code_aster's run script
// applies it; 0 when absent.
double memoryLimitOf(const Export& study);

// P ncpus <n> (EXPORT_10): the threads a command may use (the contact pairing's slave-node
// chunks); 1 when absent.
int cpusOf(const Export& study);

// P mpi_nbcpu <n> (EXPORT_12): the MPI processes of the run; stella started without mpirun starts
// itself again under mpirun with that many (doc/parallel.md); 1 when absent.
int mpiProcessesOf(const Export& study);

} // namespace stella
