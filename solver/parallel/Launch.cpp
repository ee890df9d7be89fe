// Starting stella again under mpirun (P mpi_nbcpu).

#include "solver/parallel/Launch.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <thread>
#include <unistd.h>

#ifndef STELLA_MPIEXEC
#define STELLA_MPIEXEC "mpirun"
#endif

namespace stella::mpi {

std::vector<std::string> launcherCommand(int processes, const std::vector<std::string>& arguments) {
  std::vector<std::string> command{STELLA_MPIEXEC, "-n", std::to_string(processes)};
  if (geteuid() == 0) {
    command.emplace_back("--allow-run-as-root"); // containers and sandboxes run as root
  }
  const unsigned cores = std::thread::hardware_concurrency();
  if (cores > 0 && static_cast<unsigned>(processes) > cores) {
    command.emplace_back("--oversubscribe"); // more processes than cores: allowed, slower
  }
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  command.push_back(ec ? arguments.front() : self.string());
  command.insert(command.end(), arguments.begin() + 1, arguments.end());
  return command;
}

std::string relaunchUnderMpirun(int processes, const std::vector<std::string>& arguments) {
  const std::vector<std::string> command = launcherCommand(processes, arguments);
  std::vector<char*> argv;
  for (const auto& word : command) {
    argv.push_back(const_cast<char*>(word.c_str()));
  }
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  execvp(argv.front(), argv.data());
  return std::string("cannot start ") + command.front() + ": " + std::strerror(errno);
}

} // namespace stella::mpi
