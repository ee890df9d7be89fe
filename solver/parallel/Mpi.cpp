// The MPI world of a run: OpenMPI when built with STELLA_MPI (STELLA_HAVE_MPI), else a world of one.

#include "solver/parallel/Mpi.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#ifdef STELLA_HAVE_MPI
#include <mpi.h>
#endif

namespace stella::mpi {

namespace {

int environmentNumber(const char* name, int fallback) {
  const char* text = std::getenv(name);
  return text != nullptr && *text != '\0' ? std::atoi(text) : fallback;
}

#ifdef STELLA_HAVE_MPI
bool initialisedHere = false;
// stella's own collectives (the solution's broadcast) and the agreement at the end of a run, each
// on a duplicate of the world: an agreement of a process that failed alone must never match a
// collective of MUMPS (whose MPI_Comm_dup on the world runs an allreduce) or of another phase.
MPI_Comm dataComm = MPI_COMM_NULL;
MPI_Comm agreementComm = MPI_COMM_NULL;

MPI_Comm data() {
  return dataComm != MPI_COMM_NULL ? dataComm : MPI_COMM_WORLD;
}

bool isInitialised() {
  int flag = 0;
  MPI_Initialized(&flag);
  int finalised = 0;
  MPI_Finalized(&finalised);
  return flag != 0 && finalised == 0;
}
#endif

} // namespace

std::string partitioningNote() {
  if (size() < 2) {
    return "";
  }
  return " (every process reads the mesh and the command files and assembles the whole matrix; MUMPS "
         "factorises and solves on all of them, the entries given distributed, ICNTL(18)=3; rank 0 writes "
         "the files)";
}

void failIfInjected(const char* where) {
  const char* text = std::getenv("STELLA_MPI_FAIL_RANK");
  if (text != nullptr && *text != '\0' && size() > 1 && std::atoi(text) == rank()) {
    throw std::runtime_error(std::string("fault injected on MPI rank ") + text + " in " + where +
                             " (STELLA_MPI_FAIL_RANK)");
  }
}

bool underLauncher() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr ||
         std::getenv("PMIX_RANK") != nullptr;
}

int launchedSize() {
  return environmentNumber("OMPI_COMM_WORLD_SIZE", environmentNumber("PMI_SIZE", 1));
}

int launchedRank() {
  return environmentNumber("OMPI_COMM_WORLD_RANK", environmentNumber("PMI_RANK", 0));
}

#ifdef STELLA_HAVE_MPI

bool built() {
  return true;
}

double initialise() {
  if (isInitialised()) {
    return 0.0;
  }
  if (!underLauncher()) {
    // A serial run: a singleton world without the orted daemon, shared memory and self only, no
    // network probing; allowed as root (the sandboxes run as root).
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
  }
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 0);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 0);
  const auto start = std::chrono::steady_clock::now();
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  initialisedHere = true;
  MPI_Comm_dup(MPI_COMM_WORLD, &dataComm);
  MPI_Comm_dup(MPI_COMM_WORLD, &agreementComm);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void finalise() {
  if (initialisedHere && isInitialised()) {
    for (MPI_Comm* comm : {&dataComm, &agreementComm}) {
      if (*comm != MPI_COMM_NULL) {
        MPI_Comm_free(comm);
      }
    }
    MPI_Finalize();
  }
}

int rank() {
  if (!isInitialised()) {
    return launchedRank();
  }
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  if (!isInitialised()) {
    return launchedSize();
  }
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

int fortranWorld() {
  initialise();
  return static_cast<int>(MPI_Comm_c2f(MPI_COMM_WORLD));
}

int fortranSelf() {
  initialise();
  return static_cast<int>(MPI_Comm_c2f(MPI_COMM_SELF));
}

void broadcast(double* values, long long count) {
  if (size() > 1 && count > 0) {
    MPI_Bcast(values, static_cast<int>(count), MPI_DOUBLE, 0, data());
  }
}

void broadcast(int* values, long long count) {
  if (size() > 1 && count > 0) {
    MPI_Bcast(values, static_cast<int>(count), MPI_INT, 0, data());
  }
}

void sumInPlace(double* values, long long count) {
  if (size() > 1 && count > 0) {
    MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), MPI_DOUBLE, MPI_SUM, data());
  }
}

double maxOver(double value) {
  if (size() > 1) {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, data());
  }
  return value;
}

void abortAll(int code, const std::string& message) {
  std::fprintf(stderr, "%s", message.c_str());
  std::fflush(stderr);
  if (isInitialised() && size() > 1) {
    MPI_Abort(MPI_COMM_WORLD, code);
  }
  std::_Exit(code);
}

int agreeOnExitCode(int code, double patienceSeconds, const std::string& message) {
  if (!isInitialised() || size() < 2 || agreementComm == MPI_COMM_NULL) {
    return code;
  }
  int largest = code;
  MPI_Request request = MPI_REQUEST_NULL;
  MPI_Iallreduce(&code, &largest, 1, MPI_INT, MPI_MAX, agreementComm, &request);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(patienceSeconds);
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done != 0) {
      return largest;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      abortAll(code != 0 ? code : 5, message);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

#else

bool built() {
  return false;
}
double initialise() {
  return 0.0;
}
void finalise() {}
int rank() {
  return 0;
}
int size() {
  return 1;
}
int fortranWorld() {
  return -987654;
} // the sequential MUMPS's code for its own world
int fortranSelf() {
  return -987654;
}
void broadcast(double*, long long) {}
void broadcast(int*, long long) {}
void sumInPlace(double*, long long) {}
double maxOver(double value) {
  return value;
}
void abortAll(int code, const std::string& message) {
  std::fprintf(stderr, "%s", message.c_str());
  std::fflush(stderr);
  std::_Exit(code);
}
int agreeOnExitCode(int code, double, const std::string&) {
  return code;
}

#endif

} // namespace stella::mpi
