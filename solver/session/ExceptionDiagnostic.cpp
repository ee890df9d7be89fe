#include "ExceptionDiagnostic.hpp"
#include "MemoryLimit.hpp"
#include "messages/Messages.hpp"

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
    return msg::text("OS.space");
  case EFBIG:
    return msg::text("OS.file_size");
  case EACCES:
  case EROFS:
    return msg::text("OS.access");
  case EISDIR:
    return msg::text("OS.is_folder");
  case ENOTDIR:
    return msg::text("OS.not_folder");
  default:
    return msg::text("OS.other");
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
    return msg::make("RUN_6",
                     {{"during", during},
                      {"paths", paths},
                      {"error0", error != 0 ? osReason(error) : fe->code().message()}},
                     std::move(at))
        .withNote(osAdvice(error));
  }
  if (const auto* se = dynamic_cast<const std::system_error*>(&e)) {
    return msg::make("RUN_6.2", {{"during", during}, {"what", se->what()}}, std::move(at))
        .withNote(osAdvice(se->code().value()));
  }
  if (dynamic_cast<const std::bad_alloc*>(&e) != nullptr) {
    if (activeMemoryLimit() > 0.0) {
      return msg::make("MEMORY_1", {{"during", during}, {"active_memory_limit", activeMemoryLimit()}},
                       std::move(at));
    }
    return msg::make("MEMORY_1.2", {{"during", during}}, std::move(at));
  }
  Diagnostic d = msg::make("INTERNAL_2", {{"during", during}, {"what", e.what()}}, std::move(at));
  d.kind = FailureKind::Abort;
  d.withNote(msg::text("INTERNAL_2.n1"));
  return d;
}

} // namespace stella
