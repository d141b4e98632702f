#include "apps/study/member_pool.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>

#include "apps/study/member_store.hpp"
#include "apps/study/run_member.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The worker: its output into the member's logs, then the member's run; never returns.
[[noreturn]] void work(const Study& study, const StudyMember& member, const std::string& dir) {
  const std::string mdir = memberDirectory(dir, member.index);
  const int out = open((mdir + "/run.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err = open((mdir + "/errors.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (out >= 0) dup2(out, STDOUT_FILENO);
  if (err >= 0) dup2(err, STDERR_FILENO);
  const int code = runMember(study, member, dir);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  _exit(code);  // not exit(): the parent's atexit handlers and buffers are not the worker's
}

// What a worker's wait status says: the status for study.nc and, for a signal, why.
MemberOutcome outcomeOf(int wait_status, const std::string& errors_log) {
  if (WIFEXITED(wait_status)) {
    const int code = WEXITSTATUS(wait_status);
    if (code == 0) return {kComplete, ""};
    const int status = code == kStatusBadInput || code == kStatusNotConverged ? code : kFailed;
    return {status, "exit code " + std::to_string(code) + ": " + fileTail(errors_log, 2000)};
  }
  const int sig = WIFSIGNALED(wait_status) ? WTERMSIG(wait_status) : 0;
  return {kFailed, "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) +
                       "): " + fileTail(errors_log, 2000)};
}

std::string formatSeconds(double s) {
  const long whole = static_cast<long>(s + 0.5);
  if (whole < 120) return std::to_string(whole) + " s";
  return std::to_string(whole / 60) + " min " + std::to_string(whole % 60) + " s";
}

}  // namespace

int runMemberPool(const Study& study, const std::vector<const StudyMember*>& to_run,
                  const std::string& dir, int workers, const PoolProgress& progress) {
  struct Worker {
    const StudyMember* member;
    Clock::time_point start;
  };
  std::map<pid_t, Worker> running;
  size_t next = 0;
  int done = 0, failed = 0;
  double member_seconds = 0.0;  // the wall time of the members finished, summed
  // The time left: the members not started and half of those running, at the mean time a
  // member took so far, on `workers` at once.
  const auto report = [&](const std::string& event) {
    if (!progress.out) return;
    const int finished = done + failed;
    std::string left = "time left unknown";
    if (finished > 0) {
      const double waiting = static_cast<double>(to_run.size() - next) + 0.5 * running.size();
      left = "about " + formatSeconds(member_seconds / finished * waiting / workers) + " left";
    }
    *progress.out << progress.label << "study: " << event << "; " << progress.skipped + done
                  << " of " << progress.total << " done (" << progress.skipped << " before), "
                  << running.size() << " running, " << failed << " failed, " << left << std::endl;
  };
  while (next < to_run.size() || !running.empty()) {
    while (next < to_run.size() && static_cast<int>(running.size()) < workers) {
      const StudyMember& m = *to_run[next++];
      clearOutcome(dir, m);
      fs::create_directories(memberDirectory(dir, m.index));
      std::cout.flush();
      std::cerr.flush();
      std::fflush(nullptr);
      const pid_t pid = fork();
      if (pid < 0) {
        markFailed(dir, m, kFailed, std::string("cannot start a worker: ") + std::strerror(errno));
        ++failed;
        continue;
      }
      if (pid == 0) work(study, m, dir);
      running[pid] = {&m, Clock::now()};
    }
    if (running.empty()) continue;
    int wait_status = 0;
    const pid_t pid = waitpid(-1, &wait_status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      break;  // no child left: cannot happen while `running` holds some
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const StudyMember& m = *it->second.member;
    member_seconds += std::chrono::duration<double>(Clock::now() - it->second.start).count();
    running.erase(it);
    const MemberOutcome outcome =
        outcomeOf(wait_status, memberDirectory(dir, m.index) + "/errors.log");
    if (outcome.status == kComplete) {
      ++done;
      report("member " + std::to_string(m.index) + " complete");
    } else {
      markFailed(dir, m, outcome.status, outcome.error);
      ++failed;
      report("member " + std::to_string(m.index) + " failed (" +
             outcome.error.substr(0, outcome.error.find('\n')) + ")");
    }
  }
  return failed;
}

}  // namespace flexmoor::app
