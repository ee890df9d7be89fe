// METHODE='PETSC': a PETSc Krylov solver (ALGORITHME) with its preconditioner (PRE_COND), run
// in the worker process `stella-petsc` (tools/petsc-worker, messages in PetscProtocol.hpp).
// Why a process: PETSc links the parallel MUMPS and MPI, stella the sequential MUMPS with its
// fake MPI; both define dmumps_c and the Fortran MPI symbols, so they cannot share a process.
// The worker is started at the first analysis of a study that asks for PETSc (a few tens of
// milliseconds), so the other studies run exactly as before, without MPI.
//
// The matrix goes as its upper triangle (symmetric kinds) or in full, then only its values
// while the pattern stays; the node coordinates (setNodeCoordinates) give the multigrid its
// near-null space (rigid-body modes). RESI_RELA bounds ||b - K x|| / ||b||. With
// PRE_COND='LDLT_SP' the preconditioner is kept across factorisations while every solve
// converges within REAC_PRECOND iterations (then rebuilt at the next factorisation), and a solve
// that does not converge with a kept preconditioner is retried once with a fresh one.

#include "solver/linalg/Backends.hpp"
#include "solver/linalg/PetscProtocol.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace stella::linalg {

bool petscAvailable() {
#ifdef STELLA_HAVE_PETSC
  return true;
#else
  return false;
#endif
}

namespace detail {
namespace {

namespace proto = petsc_protocol;

// STELLA_PETSC_WORKER, else `stella-petsc` next to the running program, else the build's.
std::string workerPath() {
  if (const char* e = std::getenv("STELLA_PETSC_WORKER"); e != nullptr && *e != '\0') {
    return e;
  }
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto beside = self.parent_path() / "stella-petsc";
    if (std::filesystem::exists(beside, ec)) {
      return beside.string();
    }
  }
#ifdef STELLA_PETSC_WORKER
  return STELLA_PETSC_WORKER;
#else
  throw LinearSolverError(
      "METHODE='PETSC': this stella was built without PETSc (install petsc-dev and rebuild)");
#endif
}

// The worker process and its socket; ended (Quit, then waited for) with the solver.
class Worker {
public:
  Worker() {
    int fds[2] = {-1, -1};
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
      throw LinearSolverError("PETSC: socketpair failed");
    }
    const std::string path = workerPath();
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    // OpenMPI on one process: shared memory and self only, no network probing, allowed as root
    std::vector<std::string> env;
    for (char** e = environ; *e != nullptr; ++e) {
      env.emplace_back(*e);
    }
    env.emplace_back("OMPI_MCA_ess_singleton_isolated=1"); // no orted daemon: 0.3 s less at start
    env.emplace_back("OMPI_MCA_btl=self");
    env.emplace_back("OMPI_MCA_pml=ob1");
    env.emplace_back("OMPI_ALLOW_RUN_AS_ROOT=1");
    env.emplace_back("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1");
    std::vector<char*> envp;
    for (std::string& s : env) {
      envp.push_back(s.data());
    }
    envp.push_back(nullptr);
    std::string argv0 = path;
    char* argv[] = {argv0.data(), nullptr};
    const int rc = posix_spawn(&pid_, path.c_str(), &actions, nullptr, argv, envp.data());
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (rc != 0) {
      ::close(fds[0]);
      throw LinearSolverError(
          fmt::format("PETSC: the worker {} could not be started ({})", path, std::strerror(rc)));
    }
    fd_ = fds[0];
    channel_.emplace(fd_, fd_);
  }
  ~Worker() {
    try {
      channel_->put(proto::Command::Quit);
    } catch (const std::exception&) {
      // already gone: only reap it
    }
    ::close(fd_);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;

  proto::Channel& channel() { return *channel_; }

  // VmHWM of the worker (its peak resident memory), MB; 0 when it cannot be read.
  double peakMegabytes() const {
    std::ifstream status(fmt::format("/proc/{}/status", pid_));
    std::string line;
    while (std::getline(status, line)) {
      if (line.rfind("VmHWM:", 0) == 0) {
        return std::strtod(line.c_str() + 6, nullptr) / 1024.0; // kB
      }
    }
    return 0.0;
  }

  // The reply's status and message; a failure becomes a LinearSolverError.
  std::pair<proto::Status, std::string> reply(const char* what) {
    try {
      auto status = channel_->get<proto::Status>();
      std::string message = channel_->getString();
      if (status == proto::Status::Failed) {
        throw LinearSolverError(fmt::format("PETSC: {}: {}", what, message));
      }
      return {status, message};
    } catch (const proto::ChannelClosed&) {
      throw LinearSolverError(fmt::format("PETSC: the worker stopped during the {} ({})", what, exitText()));
    }
  }
  template <class Send> void request(Send&& send, const char* what) {
    try {
      send(*channel_);
    } catch (const proto::ChannelClosed&) {
      throw LinearSolverError(fmt::format("PETSC: the worker stopped before the {} ({})", what, exitText()));
    }
  }

private:
  std::string exitText() {
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) != pid_) {
      return "still running";
    }
    pid_ = -1;
    if (WIFSIGNALED(status)) {
      return fmt::format("killed by signal {}", WTERMSIG(status));
    }
    return fmt::format("exit status {}", WEXITSTATUS(status));
  }

  pid_t pid_ = -1;
  int fd_ = -1;
  std::optional<proto::Channel> channel_;
};

class PetscSolver final : public LinearSolver {
public:
  PetscSolver(const SolverOptions& o, MatrixKind k) : LinearSolver(k), options_(o) {
    config_.algorithm = o.algorithm;
    config_.preconditioner = o.preconditioner;
    config_.relativeResidual = o.relativeResidual;
    config_.maxIterations = o.maxIterations;
    config_.fillLevel = o.fillLevel;
    config_.fill = o.fill;
    config_.pivotPercent = static_cast<std::int32_t>(std::lround(o.pivotPercent));
    config_.mumpsOrdering = 7; // RENUM='SANS': MUMPS's own choice
    config_.options = o.petscOptions;
    name_ = fmt::format("PETSC ({}, {})", o.algorithm, o.preconditioner);
  }

  std::string_view backendName() const override { return name_; }
  double factorisationFlops() const override { return 0.0; }
  std::string orderingUsed() const override { return "none"; }
  int lastIterations() const override { return iterations_; }
  double workerPeakMegabytes() const override { return worker_ ? worker_->peakMegabytes() : 0.0; }

  void setNodeCoordinates(int dimension, std::vector<double> coordinates) override {
    dimension_ = dimension;
    coordinates_ = std::move(coordinates);
    coordinatesSent_ = false;
  }

  void analyse(const SparseMatrix& a) override {
    if (!worker_) {
      worker_ = std::make_unique<Worker>();
      worker_->request(
          [&](proto::Channel& c) {
            c.put(proto::Command::Configure);
            config_.send(c);
          },
          "configuration");
      worker_->reply("configuration");
    }
    size_ = a.size();
    patternSent_ = false;
    rebuild_ = true;
  }

  void factorise(const SparseMatrix& a) override {
    if (!worker_ || a.size() != size_) {
      throw LinearSolverError("PETSC: factorisation before analysis or of another size");
    }
    if (!coordinatesSent_ && dimension_ > 1 && static_cast<int>(coordinates_.size()) == a.size()) {
      worker_->request(
          [&](proto::Channel& c) {
            c.put(proto::Command::Coordinates);
            c.put<std::int32_t>(dimension_);
            c.putArray(coordinates_.data(), coordinates_.size());
          },
          "near-null space");
      worker_->reply("near-null space");
      coordinatesSent_ = true;
    }
    sendMatrix(&a, rebuild_ || !keepsPreconditioner());
    factorised_ = true;
    rebuild_ = false;
  }

  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override {
    if (!worker_ || rhs.rows() != size_ || !factorised_) {
      throw LinearSolverError("PETSC: solve before factorisation or of the wrong size");
    }
    if (solveOnce(rhs)) {
      return;
    }
    if (keptPreconditioner_) { // the kept preconditioner no longer serves: a fresh one, once
      sendMatrix(nullptr, true);
      if (solveOnce(rhs)) {
        return;
      }
    }
    throw LinearSolverError(fmt::format("PETSC ({}, {}): no convergence: {} after {} iterations (relative "
                                        "residual {:.3e}, RESI_RELA {:.1e})",
                                        options_.algorithm, options_.preconditioner, reason_, iterations_,
                                        residual_, options_.relativeResidual));
  }

private:
  bool keepsPreconditioner() const { return options_.preconditioner == "LDLT_SP"; }

  // `a` null: the values of the last matrix, kept by the worker (a rebuild of its preconditioner).
  void sendMatrix(const SparseMatrix* a, bool rebuild) {
    const bool same = patternSent_;
    const std::int32_t blockSize = coordinatesSent_ ? dimension_ : 1;
    worker_->request(
        [&](proto::Channel& c) {
          c.put(proto::Command::Matrix);
          c.put<std::int64_t>(size_);
          c.put<std::int32_t>(blockSize);
          c.put<std::int32_t>(kind() == MatrixKind::Unsymmetric ? 0 : 1);
          c.put<std::int32_t>(same ? 1 : 0);
          c.put<std::int32_t>(rebuild ? 1 : 0);
          if (!same) {
            const SparsePattern& p = a->pattern();
            c.putArray(p.rowStart.data(), p.rowStart.size());
            static_assert(sizeof(int) == sizeof(std::int32_t));
            c.putArray(p.columns.data(), p.columns.size());
          }
          if (a != nullptr) {
            c.putArray(a->values().data(), a->values().size());
          } else {
            c.putArray<double>(nullptr, 0);
          }
        },
        "matrix");
    worker_->reply("matrix");
    patternSent_ = true;
    keptPreconditioner_ = !rebuild;
  }

  // One Solve request; false when the KSP did not converge (reason_ says why).
  bool solveOnce(Eigen::Ref<Eigen::MatrixXd> rhs) {
    Eigen::MatrixXd block = rhs; // contiguous, column-major
    worker_->request(
        [&](proto::Channel& c) {
          c.put(proto::Command::Solve);
          c.put<std::int32_t>(static_cast<std::int32_t>(block.cols()));
          c.putArray(block.data(), static_cast<std::size_t>(block.size()));
        },
        "solve");
    const auto [status, message] = worker_->reply("solve");
    iterations_ = worker_->channel().get<std::int32_t>();
    residual_ = worker_->channel().get<double>();
    if (status != proto::Status::Ok) {
      reason_ = message;
      rebuild_ = true;
      return false;
    }
    worker_->channel().getArrayInto(block.data(), static_cast<std::size_t>(block.size()));
    rhs = block;
    if (iterations_ > options_.preconditionerReuseIterations) {
      rebuild_ = true; // REAC_PRECOND: rebuilt at the next factorisation
    }
    return true;
  }

  SolverOptions options_;
  std::string name_;
  proto::Configuration config_;
  std::unique_ptr<Worker> worker_;
  int size_ = -1;
  int dimension_ = 0;
  std::vector<double> coordinates_;
  bool coordinatesSent_ = false;
  bool patternSent_ = false;
  bool rebuild_ = true;
  bool keptPreconditioner_ = false;
  bool factorised_ = false;
  int iterations_ = 0;
  double residual_ = 0.0;
  std::string reason_;
};

} // namespace

std::unique_ptr<LinearSolver> makePetsc(const SolverOptions& o, MatrixKind k) {
  return std::make_unique<PetscSolver>(o, k);
}

} // namespace detail
} // namespace stella::linalg
