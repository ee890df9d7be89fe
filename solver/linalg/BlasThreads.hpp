#pragma once
// Threads of the BLAS under MUMPS and CHOLMOD (their dense frontal/supernodal kernels).
//
// The BLAS is the one the system's alternatives select (libblas.so.3): tools/install-deps picks
// OpenBLAS's pthread variant (libopenblas0-pthread), whose thread count is set at run time with
// openblas_set_num_threads. The function is looked up at run time, so with another BLAS (serial
// OpenBLAS, reference BLAS) setting the count does nothing and blasThreads() says 1.
//
// The count a job uses (doc/fem.md "Threads"): the environment variable STELLA_BLAS_THREADS when
// set (a whole number from 1 to 1024), else the export's `P ncpus`, else 1.

#include <optional>
#include <string>

namespace stella::linalg {

// Sets the BLAS's thread count (n >= 1); returns the count in effect afterwards.
int setBlasThreads(int n);
// The BLAS's thread count in effect (1 when the BLAS cannot tell).
int blasThreads();
// The BLAS library's own description (OpenBLAS's openblas_get_config: version, variant), or "".
std::string blasDescription();

// STELLA_BLAS_THREADS from the environment: nullopt if unset; throws std::invalid_argument
// (message naming the variable and the value) when it is not a whole number from 1 to 1024.
std::optional<int> blasThreadsFromEnvironment();
// The thread count for a job with `P ncpus` = exportCpus: the environment's, else exportCpus.
int blasThreadsFor(int exportCpus);
// Sets the BLAS threads of a job with `P ncpus` = exportCpus (blasThreadsFor) and returns the
// message-file line that says so; an empty line when the count is 1 and the environment variable
// is unset (the default says nothing). A malformed STELLA_BLAS_THREADS is reported on the line
// and the export's count used.
std::string applyBlasThreads(int exportCpus);

} // namespace stella::linalg
