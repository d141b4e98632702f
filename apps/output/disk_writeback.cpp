#include "apps/output/disk_writeback.hpp"

#include <fcntl.h>
#include <unistd.h>

namespace flexmoor::app {

DiskWriteback::DiskWriteback(const std::string& path)
    : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW)) {}

DiskWriteback::~DiskWriteback() {
  if (fd_ >= 0) ::close(fd_);
}

void DiskWriteback::written(size_t bytes) {
  pending_ += bytes;
  if (pending_ < kWritebackBytes || fd_ < 0) return;
  pending_ = 0;
#ifdef SYNC_FILE_RANGE_WRITE
  if (::sync_file_range(fd_, 0, 0, SYNC_FILE_RANGE_WRITE) == 0) ++started_;
#endif
}

}  // namespace flexmoor::app
