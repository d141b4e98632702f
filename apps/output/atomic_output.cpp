#include "apps/output/atomic_output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
  throw std::runtime_error(path + ": " + what + ": " + std::strerror(error));
}

// Flushes the file or directory at `path` to the disk; best effort (a file system that cannot
// sync a directory loses nothing that rename has not already made visible).
void syncToDisk(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

std::string directoryOf(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

// A new file next to `path`, ".NAME.tmp-PID-K", created exclusively (O_EXCL never follows a
// link) with the permissions of any new file (0666 less the umask).
int createTemporary(const std::string& path, std::string& temporary) {
  const fs::path p(path);
  for (int k = 0;; ++k) {
    temporary = (p.parent_path() / ("." + p.filename().string() + ".tmp-" +
                                    std::to_string(::getpid()) + "-" + std::to_string(k)))
                    .string();
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
}

bool writeAll(int fd, const std::string& text) {
  for (size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return ::fsync(fd) == 0;
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& text) {
  std::string temporary;
  const int fd = createTemporary(path, temporary);
  if (fd < 0) fail(path, "cannot write a temporary file in its directory", errno);
  const bool written = writeAll(fd, text);
  const int error = errno;
  if (::close(fd) != 0 || !written) {
    ::unlink(temporary.c_str());
    fail(path, "cannot write the file", written ? errno : error);
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_error = errno;
    ::unlink(temporary.c_str());
    fail(path, "cannot put the written file in place", rename_error);
  }
  syncToDisk(directoryOf(path), O_RDONLY | O_DIRECTORY);
}

void moveIntoPlace(const std::string& written, const std::string& path) {
  syncToDisk(written, O_RDONLY);
  if (::rename(written.c_str(), path.c_str()) != 0)
    fail(path, "cannot put " + written + " in place", errno);
  syncToDisk(directoryOf(path), O_RDONLY | O_DIRECTORY);
}

void removeEntry(const std::string& path) {
  if (::unlink(path.c_str()) != 0 && errno != ENOENT) fail(path, "cannot remove", errno);
}

}  // namespace flexmoor::app
