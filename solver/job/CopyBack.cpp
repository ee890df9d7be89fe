#include "CopyBack.hpp"

#include "solver/session/ExceptionDiagnostic.hpp"

#include <cerrno>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace stella {

namespace fs = std::filesystem;

namespace {

class Descriptor {
public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) {
      ::close(fd_);
    }
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }
  // close(2) reports the errors of delayed writes (NFS, quotas): checked.
  int release() {
    const int status = ::close(fd_);
    fd_ = -1;
    return status;
  }

private:
  int fd_;
};

bool writeAll(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) {
        continue;
      }
      return false;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

} // namespace

std::optional<std::string> copyResultFile(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  if (!to.parent_path().empty()) {
    fs::create_directories(to.parent_path(), ec);
    if (ec) {
      return fmt::format("cannot make the folder {}: {}", to.parent_path().string(), osReason(ec.value()));
    }
  }
  Descriptor in(::open(from.c_str(), O_RDONLY | O_CLOEXEC));
  if (in.get() < 0) {
    return fmt::format("cannot read {}: {}", from.string(), osReason(errno));
  }
  Descriptor out(::open(to.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
  if (out.get() < 0) {
    return fmt::format("cannot open {} for writing: {}", to.string(), osReason(errno));
  }
  struct stat target {};
  const bool regular = ::fstat(out.get(), &target) == 0 && S_ISREG(target.st_mode);
  auto failed = [&](const std::string& what) -> std::optional<std::string> {
    const int error = errno;
    if (regular) {
      ::unlink(to.c_str()); // a truncated copy would look like the real file
    }
    return fmt::format("{} {}: {}{}", what, to.string(), osReason(error),
                       regular ? " (the partial copy was removed)" : "");
  };
  std::vector<char> buffer(1 << 16);
  for (;;) {
    const ssize_t n = ::read(in.get(), buffer.data(), buffer.size());
    if (n < 0) {
      if (errno == EINTR) {
        continue;
      }
      return fmt::format("cannot read {}: {}", from.string(), osReason(errno));
    }
    if (n == 0) {
      break;
    }
    if (!writeAll(out.get(), buffer.data(), static_cast<std::size_t>(n))) {
      return failed("cannot write");
    }
  }
  if (out.release() != 0) {
    return failed("cannot complete");
  }
  return std::nullopt;
}

} // namespace stella
