#pragma once
// The messages between stella (linalg/PetscSolver.cpp) and its PETSc worker process
// (tools/petsc-worker, `stella-petsc`). PETSc links the parallel MUMPS and MPI while stella links
// the sequential MUMPS with its fake MPI: both define dmumps_c and the Fortran MPI symbols, so
// PETSc runs in a process of its own, started only when a study asks for METHODE='PETSC'.
// Header only and free of PETSc, MPI and Eigen: both sides include it.
//
// One stream socket, requests from stella, one reply per request:
//   Configure  KSP type, PC type, RESI_RELA, NMAX_ITER, fill level and fill (ICC), PCENT_PIVOT,
//              MUMPS ordering (LDLT_SP), OPTION_PETSC               -> Status
//   Matrix     n, block size, upper-triangle flag, same-pattern flag, CSR (row starts, columns,
//              values), rebuild-preconditioner flag                    -> Status
//   Coordinates  per block of `block size` equations, the coordinates of its node (the near-null
//              space of the multigrid: rigid-body modes)               -> Status
//   Solve      k right-hand sides (n x k, column-major)                -> Status, iterations,
//              relative residual, then the k solutions when Status is Ok
//   Quit       (no reply)
// Status: Ok, NotConverged (message: the KSP's reason) or Failed (message: PETSc's error).

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <cerrno>
#include <sys/socket.h>
#include <unistd.h>

namespace stella::petsc_protocol {

enum class Command : std::int32_t { Configure = 1, Matrix = 2, Coordinates = 3, Solve = 4, Quit = 5 };
enum class Status : std::int32_t { Ok = 0, NotConverged = 1, Failed = 2 };

class ChannelClosed : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Blocking reads and writes of whole buffers on a file descriptor (a socket: writes use send()
// with MSG_NOSIGNAL so a dead peer gives an error, not SIGPIPE).
class Channel {
public:
  explicit Channel(int in, int out) : in_(in), out_(out) {}

  void write(const void* data, std::size_t bytes) {
    const char* p = static_cast<const char*>(data);
    while (bytes > 0) {
      const ssize_t w = ::send(out_, p, bytes, MSG_NOSIGNAL);
      if (w < 0 && errno == EINTR) {
        continue;
      }
      if (w <= 0) {
        throw ChannelClosed(std::string("PETSc channel: write failed: ") + std::strerror(errno));
      }
      p += w;
      bytes -= static_cast<std::size_t>(w);
    }
  }
  void read(void* data, std::size_t bytes) {
    char* p = static_cast<char*>(data);
    while (bytes > 0) {
      const ssize_t r = ::read(in_, p, bytes);
      if (r < 0 && errno == EINTR) {
        continue;
      }
      if (r <= 0) {
        throw ChannelClosed(r == 0 ? "PETSc channel: closed by the other side"
                                   : std::string("PETSc channel: read failed: ") + std::strerror(errno));
      }
      p += r;
      bytes -= static_cast<std::size_t>(r);
    }
  }

  template <class T> void put(const T& v) { write(&v, sizeof(T)); }
  template <class T> T get() {
    T v{};
    read(&v, sizeof(T));
    return v;
  }
  void putString(const std::string& s) {
    put<std::int64_t>(static_cast<std::int64_t>(s.size()));
    write(s.data(), s.size());
  }
  std::string getString() {
    std::string s(static_cast<std::size_t>(get<std::int64_t>()), '\0');
    read(s.data(), s.size());
    return s;
  }
  template <class T> void putArray(const T* data, std::size_t count) {
    put<std::int64_t>(static_cast<std::int64_t>(count));
    write(data, count * sizeof(T));
  }
  template <class T> std::vector<T> getArray() {
    std::vector<T> v(static_cast<std::size_t>(get<std::int64_t>()));
    read(v.data(), v.size() * sizeof(T));
    return v;
  }
  // Into an existing buffer of the expected size (large vectors: no reallocation).
  template <class T> void getArrayInto(T* data, std::size_t expected) {
    const auto count = static_cast<std::size_t>(get<std::int64_t>());
    if (count != expected) {
      throw ChannelClosed("PETSc channel: unexpected array size");
    }
    read(data, count * sizeof(T));
  }

private:
  int in_;
  int out_;
};

// The SOLVEUR keywords the worker needs (Configure).
struct Configuration {
  std::string algorithm = "FGMRES";    // ALGORITHME: CG, GMRES, GCR, FGMRES
  std::string preconditioner = "GAMG"; // PRE_COND
  double relativeResidual = 1e-6;      // RESI_RELA: ||b - A x|| / ||b||
  std::int32_t maxIterations = 0;      // NMAX_ITER (0: PETSc's default, 10000)
  std::int32_t fillLevel = 0;          // NIVE_REMPLISSAGE (LDLT_INC)
  double fill = 1.0;                   // REMPLISSAGE (LDLT_INC)
  std::int32_t pivotPercent = 20;      // PCENT_PIVOT (LDLT_SP)
  std::int32_t mumpsOrdering = 7;      // ICNTL(7) of the LDLT_SP factorisation
  std::string options;                 // OPTION_PETSC

  void send(Channel& c) const {
    c.putString(algorithm);
    c.putString(preconditioner);
    c.put(relativeResidual);
    c.put(maxIterations);
    c.put(fillLevel);
    c.put(fill);
    c.put(pivotPercent);
    c.put(mumpsOrdering);
    c.putString(options);
  }
  static Configuration receive(Channel& c) {
    Configuration o;
    o.algorithm = c.getString();
    o.preconditioner = c.getString();
    o.relativeResidual = c.get<double>();
    o.maxIterations = c.get<std::int32_t>();
    o.fillLevel = c.get<std::int32_t>();
    o.fill = c.get<double>();
    o.pivotPercent = c.get<std::int32_t>();
    o.mumpsOrdering = c.get<std::int32_t>();
    o.options = c.getString();
    return o;
  }
};

} // namespace stella::petsc_protocol
