#pragma once
// Runs study members in worker processes, at most `workers` at once. Processes, not threads:
// netCDF and HDF5 are not thread-safe, so every member writes its files from a process of its
// own; and a member that crashes or is killed takes down only its worker. Each worker is a fork
// of the caller (the study already read and checked), runs runMember and exits with its code;
// its stdout goes to the member's run.log, its stderr to errors.log. A member that fails (exit
// code 2, 3 or 4, or a signal) is recorded by the caller with the end of errors.log
// (member_store.hpp) and the others carry on.
#include <ostream>
#include <string>
#include <vector>

#include "apps/study/study.hpp"

namespace flexmoor::app {

struct PoolProgress {
  std::ostream* out = nullptr;  // progress lines; null: none
  std::string label;            // before each line ("rank 1: ")
  int skipped = 0;              // members complete already, for the counts shown
  int total = 0;                // members of the study (of this rank)
};

// Returns how many of `to_run` failed.
int runMemberPool(const Study& study, const std::vector<const StudyMember*>& to_run,
                  const std::string& dir, int workers, const PoolProgress& progress);

}  // namespace flexmoor::app
