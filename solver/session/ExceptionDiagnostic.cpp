#include "ExceptionDiagnostic.hpp"
#include "MemoryLimit.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <new>
#include <system_error>

namespace stella {

namespace {

std::string errnoName(int error) {
  switch (error) {
  case ENOSPC:
    return "ENOSPC";
  case EFBIG:
    return "EFBIG";
  case EACCES:
    return "EACCES";
  case EROFS:
    return "EROFS";
  case EISDIR:
    return "EISDIR";
  case ENOTDIR:
    return "ENOTDIR";
  case ENOENT:
    return "ENOENT";
  case EDQUOT:
    return "EDQUOT";
  case EIO:
    return "EIO";
  case EINVAL:
    return "EINVAL";
  default:
    return "errno " + std::to_string(error);
  }
}

} // namespace

std::string osAdvice(int error) {
  switch (error) {
  case ENOSPC:
  case EDQUOT:
    return "free some space on that file system (or raise the quota), or write the results elsewhere";
  case EFBIG:
    return "the file-size limit of the process was reached (ulimit -f): raise it, or write fewer steps "
           "or fields";
  case EACCES:
  case EROFS:
    return "make the folder writable, or give a destination you can write";
  case EISDIR:
    return "the destination is a folder: give a file name";
  case ENOTDIR:
    return "a part of the destination path is a file, not a folder: correct the path";
  default:
    return "check the path and the file system";
  }
}

std::string osReason(int error) {
  return fmt::format("{} ({})", std::strerror(error), errnoName(error));
}

Diagnostic diagnosticOf(const std::exception& e, const std::string& during, SourceLocation at) {
  if (const auto* fe = dynamic_cast<const std::filesystem::filesystem_error*>(&e)) {
    std::string paths = fe->path1().string();
    if (!fe->path2().empty()) {
      paths += " -> " + fe->path2().string();
    }
    const int error =
        fe->code().category() == std::generic_category() || fe->code().category() == std::system_category()
            ? fe->code().value()
            : 0;
    return Diagnostic::fatal("RUN_6",
                             fmt::format("a file operation failed while {}: {}: {}", during, paths,
                                         error != 0 ? osReason(error) : fe->code().message()),
                             std::move(at))
        .withNote(osAdvice(error));
  }
  if (const auto* se = dynamic_cast<const std::system_error*>(&e)) {
    return Diagnostic::fatal("RUN_6",
                             fmt::format("an operating-system call failed while {}: {}", during, se->what()),
                             std::move(at))
        .withNote(osAdvice(se->code().value()));
  }
  if (dynamic_cast<const std::bad_alloc*>(&e) != nullptr) {
    if (activeMemoryLimit() > 0.0) {
      return Diagnostic::fatal("MEMORY_1",
                               fmt::format("not enough memory while {}: the run's limit of {:g} MiB (P "
                                           "memory_limit) is reached",
                                           during, activeMemoryLimit()),
                               std::move(at))
          .withNote("raise P memory_limit in the export, or use a coarser mesh");
    }
    return Diagnostic::fatal("MEMORY_1", "not enough memory while " + during, std::move(at))
        .withNote("use a coarser mesh or a machine with more memory");
  }
  Diagnostic d = Diagnostic::fatal("INTERNAL_2", "internal error in stella while " + during + ": " + e.what(),
                                   std::move(at));
  d.kind = FailureKind::Abort;
  d.withNote("this is a bug in stella, not in your study: please report it with the command file");
  return d;
}

} // namespace stella
