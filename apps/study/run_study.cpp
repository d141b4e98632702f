#include "apps/study/run_study.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "apps/output/output_lock.hpp"
#include "apps/run/run_case.hpp"
#include "apps/study/member_pool.hpp"
#include "apps/study/member_store.hpp"
#include "apps/study/study_file.hpp"

namespace flexmoor::app {

std::vector<const StudyMember*> membersToRun(const Study& study, const std::string& dir, int rank,
                                             int ranks, int& skipped, int& assigned) {
  std::vector<const StudyMember*> to_run;
  skipped = assigned = 0;
  for (const StudyMember& m : study.members) {
    if ((m.index - 1) % ranks != rank) continue;
    ++assigned;
    if (isComplete(dir, m))
      ++skipped;
    else
      to_run.push_back(&m);
  }
  return to_run;
}

int runStudyMembers(const Study& study, const std::string& dir, int workers, int rank, int ranks,
                    std::ostream& progress) {
  std::filesystem::create_directories(dir);
  PoolProgress p;
  p.out = &progress;
  p.label = ranks > 1 ? "rank " + std::to_string(rank) + ": " : "";
  const std::vector<const StudyMember*> to_run =
      membersToRun(study, dir, rank, ranks, p.skipped, p.total);
  progress << p.label << "study: " << p.total << " members, " << p.skipped << " complete already, "
           << to_run.size() << " to run on " << workers << " worker" << (workers == 1 ? "" : "s")
           << std::endl;
  return runMemberPool(study, to_run, dir, workers, p);
}

int finishStudy(const Study& study, const std::string& dir, std::ostream& log) {
  const int complete = writeStudyFile(study, dir);
  const int failed = static_cast<int>(study.members.size()) - complete;
  log << "study: " << complete << " of " << study.members.size() << " members complete"
      << (failed ? ", " + std::to_string(failed) + " failed (status and error in study.nc)" : "")
      << "\nresults: " << (std::filesystem::path(dir) / "study.nc").string() << "\n";
  return failed ? kRunFailed : kSuccess;
}

int runStudy(const Study& study, const StudyOptions& options, std::ostream& log) {
  std::filesystem::create_directories(options.output_dir);
  const std::string lock_file =
      (std::filesystem::path(options.output_dir) / ".study.lock").string();
  const OutputLock lock(lock_file, options.output_dir + ": another study is running there (" +
                                       lock_file +
                                       " is locked); this one is refused: let that one "
                                       "end or choose another directory with -o");
  const int cores = static_cast<int>(std::thread::hardware_concurrency());
  const int workers = options.workers > 0 ? options.workers : std::max(1, cores);
  runStudyMembers(study, options.output_dir, workers, 0, 1, log);
  return finishStudy(study, options.output_dir, log);
}

}  // namespace flexmoor::app
