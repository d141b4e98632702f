#pragma once
// Early writeback of a file that another library writes (HDF5 writes the netCDF file through its
// own descriptor). A run that streams a large file leaves most of it in the page cache, and the
// fsync that puts the file in place (atomic_output.hpp) then waits for all of it to reach the
// disk: 20 ms for the 47 MB of the demo case written every step, 10% of the run. Told of every
// batch of bytes written, this asks the kernel, every kWritebackBytes, to start writing the
// file's dirty pages without waiting for them (Linux sync_file_range), so that the disk works
// while the run goes on and the last fsync waits only for the rest. Best effort: where the file
// cannot be opened again or the call is missing, nothing is asked and nothing changes.
#include <cstddef>
#include <string>

namespace flexmoor::app {

class DiskWriteback {
 public:
  static constexpr size_t kWritebackBytes = 4u << 20;

  explicit DiskWriteback(const std::string& path);
  ~DiskWriteback();
  DiskWriteback(const DiskWriteback&) = delete;
  DiskWriteback& operator=(const DiskWriteback&) = delete;

  // `bytes` more were written to the file.
  void written(size_t bytes);
  // How many times writeback was asked for so far.
  int started() const { return started_; }

 private:
  int fd_ = -1;
  size_t pending_ = 0;  // bytes written since writeback was last asked for
  int started_ = 0;
};

}  // namespace flexmoor::app
