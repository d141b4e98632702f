#include "apps/output/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace flexmoor::app {

OutputLock::OutputLock(const std::string& path, const std::string& busy)
    : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666)) {
  if (fd_ < 0)
    throw std::runtime_error(path + ": cannot create the lock file: " + std::strerror(errno));
  int status;
  do status = ::flock(fd_, LOCK_EX | LOCK_NB);
  while (status != 0 && errno == EINTR);
  if (status != 0) {
    const int error = errno;
    ::close(fd_);
    if (error == EWOULDBLOCK) throw std::runtime_error(busy);
    throw std::runtime_error(path + ": cannot lock: " + std::strerror(error));
  }
}

OutputLock::~OutputLock() { ::close(fd_); }  // closing the file releases the lock

}  // namespace flexmoor::app
