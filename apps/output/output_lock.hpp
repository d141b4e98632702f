#pragma once
// An exclusive lock on a lock file, so that two runs never write the same outputs at once:
// flock(2) on the file, held while the object lives and released by the kernel when the process
// ends in any way (a killed run leaves no stale lock). The (empty) lock file stays in place:
// removing it would let a third run lock a new file while the second still holds the old one.
#include <string>

namespace flexmoor::app {

class OutputLock {
 public:
  // Locks `path`, creating it when needed. Throws std::runtime_error `busy` when another process
  // holds the lock, and "PATH: cannot create the lock file: <errno text>" when it cannot be made.
  OutputLock(const std::string& path, const std::string& busy);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace flexmoor::app
