// stella-petsc: the PETSc worker of SOLVEUR METHODE='PETSC'. Reads requests on its standard
// input and answers on its standard output (a socket stella passes; messages in
// solver/linalg/PetscProtocol.hpp); PETSc's own prints go to the standard error. Ends on Quit or
// when stella closes the socket.

#include "KspSystem.hpp"

#include <petscsys.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <memory>
#include <sys/prctl.h>
#include <unistd.h>

namespace proto = stella::petsc_protocol;

namespace {

void reply(proto::Channel& c, proto::Status status, const std::string& message) {
  c.put(status);
  c.putString(message);
}

void serve(proto::Channel& c) {
  std::unique_ptr<stella::petsc_worker::KspSystem> system;
  for (;;) {
    const auto command = c.get<proto::Command>();
    try {
      switch (command) {
      case proto::Command::Quit:
        return;
      case proto::Command::Configure:
        system = std::make_unique<stella::petsc_worker::KspSystem>(proto::Configuration::receive(c));
        reply(c, proto::Status::Ok, "");
        break;
      case proto::Command::Matrix: {
        stella::petsc_worker::MatrixMessage m = stella::petsc_worker::MatrixMessage::receive(c);
        if (!system) {
          throw std::runtime_error("matrix before configuration");
        }
        system->setMatrix(m);
        reply(c, proto::Status::Ok, "");
        break;
      }
      case proto::Command::Coordinates: {
        const auto dimension = c.get<std::int32_t>();
        auto coordinates = c.getArray<double>();
        if (!system) {
          throw std::runtime_error("coordinates before configuration");
        }
        system->setCoordinates(dimension, std::move(coordinates));
        reply(c, proto::Status::Ok, "");
        break;
      }
      case proto::Command::Solve: {
        const auto columns = c.get<std::int32_t>();
        auto rhs = c.getArray<double>();
        if (!system) {
          throw std::runtime_error("solve before configuration");
        }
        const stella::petsc_worker::SolveReport r = system->solve(rhs, columns);
        reply(c, r.converged ? proto::Status::Ok : proto::Status::NotConverged, r.message);
        c.put<std::int32_t>(r.iterations);
        c.put<double>(r.relativeResidual);
        if (r.converged) {
          c.putArray(rhs.data(), rhs.size());
        }
        break;
      }
      default:
        reply(c, proto::Status::Failed, "unknown request");
        return;
      }
    } catch (const proto::ChannelClosed&) {
      throw;
    } catch (const std::exception& e) {
      reply(c, proto::Status::Failed, e.what());
    }
  }
}

} // namespace

int main(int argc, char** argv) {
  // Ends with stella even in the middle of a solve (a run stopped by its time limit or a signal).
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() == 1) {
    return 0; // stella ended before the line above
  }
  // The socket is the standard input and output: keep them for the channel and send whatever
  // PETSc or MPI print to the standard error.
  const int in = dup(STDIN_FILENO);
  const int out = dup(STDOUT_FILENO);
  dup2(STDERR_FILENO, STDOUT_FILENO);
  int petscArgc = 1; // no command-line options: OPTION_PETSC comes through Configure
  if (PetscInitialize(&petscArgc, &argv, nullptr, nullptr) != 0) {
    std::fprintf(stderr, "stella-petsc: PetscInitialize failed\n");
    return 2;
  }
  (void)argc;
  stella::petsc_worker::installErrorHandler();
  proto::Channel channel(in, out);
  int status = 0;
  try {
    serve(channel);
  } catch (const proto::ChannelClosed&) {
    status = 0; // stella ended (or was killed): nothing to answer
  }
  PetscFinalize();
  return status;
}
