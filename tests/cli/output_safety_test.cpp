// Results are never lost or corrupted, through the command as a user meets it: a rerun
// while a reader holds the old file, a rerun that fails, two runs of one case at once, a killed
// run, links planted at the outputs, stale files of an earlier run and the default directory.
#include <gtest/gtest.h>
#include <netcdf.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

using flexmoor::test::CliRun;
using flexmoor::test::flexmoor;
using flexmoor::test::readFile;
using flexmoor::test::scratch;

// The demo case (pretension, modes, 60 time steps: about 0.1 s) under the name `name`, its time
// steps `steps` of 5 ms written every step and its static step called `static_name`.
std::string demoCase(const std::string& name, int steps = 60,
                     const std::string& static_name = "pretension") {
  std::string text = readFile(fs::path(FLEXMOOR_SOURCE_DIR) / "cases/demo/driven-taut-cable.yaml");
  text = std::regex_replace(text, std::regex("name: driven-taut-cable"), "name: " + name);
  text = std::regex_replace(text, std::regex("name: pretension\\}"), "name: " + static_name + "}");
  text = std::regex_replace(text, std::regex("schedule: \\[.*\\],"),
                            "schedule: [{dt: 0.005 s, steps: " + std::to_string(steps) + "}],");
  text = std::regex_replace(text, std::regex("output_every: 4"), "output_every: 1");
  return text;
}

fs::path writeCase(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path file = dir / (name + ".yaml");
  std::ofstream(file) << text;
  return file;
}

// Every regular file of `dir` (not below it) and its content.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file()) files[entry.path().filename().string()] = readFile(entry.path());
  return files;
}

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.insert(entry.path().filename().string());
  return names;
}

ino_t inodeOf(const fs::path& p) {
  struct stat s {};
  return ::stat(p.c_str(), &s) == 0 ? s.st_ino : 0;
}

size_t records(int file) {
  int dim = -1;
  size_t length = 0;
  EXPECT_EQ(nc_inq_dimid(file, "time", &dim), NC_NOERR);
  EXPECT_EQ(nc_inq_dimlen(file, dim, &length), NC_NOERR);
  return length;
}

std::vector<double> times(int file) {
  std::vector<double> t(records(file));
  int var = -1;
  EXPECT_EQ(nc_inq_varid(file, "time", &var), NC_NOERR);
  if (!t.empty()) {
    EXPECT_EQ(nc_get_var_double(file, var, t.data()), NC_NOERR);
  }
  return t;
}

// `flexmoor ARGS` started in the background, its output to `log`; SIGKILLed if still running
// when this goes out of scope.
class BackgroundRun {
 public:
  BackgroundRun(const std::string& args, const fs::path& log) {
    const std::string command =
        "exec " + std::string(FLEXMOOR_BINARY) + " " + args + " >" + log.string() + " 2>&1";
    pid_ = fork();
    if (pid_ == 0) {
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
  }
  ~BackgroundRun() { kill(); }
  void kill() {
    if (!running()) return;
    ::kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  bool running() {
    if (pid_ > 0 && waitpid(pid_, nullptr, WNOHANG) != 0) pid_ = -1;  // it ended (and is reaped)
    return pid_ > 0;
  }

 private:
  pid_t pid_ = -1;
};

// Waits up to `limit` for `p` to exist.
bool waitFor(const fs::path& p, std::chrono::seconds limit = std::chrono::seconds(60)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!fs::exists(p) && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return fs::exists(p);
}

// The old bug: nc_create with NC_CLOBBER truncated the file under the reader, then failed on
// HDF5's lock (exit 4, old results gone). Now the rerun writes a new file and renames it over
// the old name; the reader keeps reading the old one whole.
TEST(OutputSafety, RerunSucceedsWhileAReaderHoldsTheOldResultsOpen) {
  const fs::path dir = scratch("reader-open");
  const fs::path file = writeCase(dir, "held", demoCase("held"));
  ASSERT_EQ(flexmoor("run " + file.string() + " -o " + dir.string()).exit_code, 0);
  const ino_t old_inode = inodeOf(dir / "held.nc");
  int reader = -1;
  ASSERT_EQ(nc_open((dir / "held.nc").c_str(), NC_NOWRITE, &reader), NC_NOERR);
  const std::vector<double> before = times(reader);
  ASSERT_EQ(before.size(), 1u + 60u);  // the dynamic step's start, then every time step

  const CliRun rerun = flexmoor("run " + file.string() + " -o " + dir.string());
  EXPECT_EQ(rerun.exit_code, 0) << rerun.output;
  EXPECT_EQ(times(reader), before);  // the held file, read to its end after the rerun
  nc_close(reader);
  EXPECT_NE(inodeOf(dir / "held.nc"), old_inode);
  int fresh = -1;
  ASSERT_EQ(nc_open((dir / "held.nc").c_str(), NC_NOWRITE, &fresh), NC_NOERR);
  EXPECT_EQ(times(fresh), before);  // the same case gives the same records
  nc_close(fresh);
}

// A rerun that fails after it has started writing leaves every file of the earlier run
// byte-identical and says where this run's records are. The failure is a full disk, made by a
// file-size limit (prlimit, util-linux) of 3.5 MB with SIGXFSZ ignored, so the write fails with
// EFBIG: the rerun's 4,000 records each written outgrow the first chunks of its record
// variables (2.5 MB) when the second ones are allocated. Exit 4, no crash (HDF5's own cleanup at
// exit crashed on the file whose close had failed: netcdf_file.hpp), and the cause named.
TEST(OutputSafety, FailedRerunLeavesTheEarlierResultsByteIdentical) {
  const fs::path dir = scratch("failed-rerun");
  ASSERT_EQ(
      flexmoor("run " + writeCase(dir, "kept", demoCase("kept")).string() + " -o " + dir.string())
          .exit_code,
      0);
  fs::remove(dir / "kept.yaml");
  const auto earlier = contents(dir);
  ASSERT_EQ(earlier.size(), 6u);  // kept.nc, kept-1/2/3.vtk, kept.summary.json, .kept.lock

  const fs::path failing = dir.parent_path() / ("failing-" + std::to_string(getpid()) + ".yaml");
  std::ofstream(failing) << demoCase("kept", 4000);
  const CliRun r = flexmoor::test::command("trap '' XFSZ; exec prlimit --fsize=3500000 " +
                                           std::string(FLEXMOOR_BINARY) + " run " +
                                           failing.string() + " -o " + dir.string());
  fs::remove(failing);
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.errors.find("(File too large)"), std::string::npos) << r.errors;
  EXPECT_NE(r.errors.find("kept.nc is left as the last finished run wrote it"), std::string::npos)
      << r.errors;
  EXPECT_NE(r.errors.find("kept.nc.partial"), std::string::npos) << r.errors;
  auto after = contents(dir);
  EXPECT_EQ(after.count("kept.nc.partial"), 1u);
  after.erase("kept.nc.partial");
  EXPECT_TRUE(after == earlier) << "an earlier output changed";
}

// A long run of the demo case: 10^6 time steps, each written (a few minutes; killed early).
std::string longCase(const std::string& name) { return demoCase(name, 1000000); }

// Two runs of one case into one directory at once: the second is refused before it writes
// anything (the old bug: both wrote one file and the first reported success with a file that
// ncdump could not read).
TEST(OutputSafety, ASecondRunOfTheCaseIntoTheSameDirectoryIsRefused) {
  const fs::path dir = scratch("two-runs");
  const fs::path file = writeCase(dir, "twice", longCase("twice"));
  BackgroundRun first("run " + file.string() + " -o " + dir.string(), dir / "first.log");
  ASSERT_TRUE(waitFor(dir / "twice.nc.partial")) << readFile(dir / "first.log");
  const ino_t streaming = inodeOf(dir / "twice.nc.partial");

  const CliRun second = flexmoor("run " + file.string() + " -o " + dir.string());
  EXPECT_EQ(second.exit_code, 4) << second.output;
  EXPECT_NE(second.errors.find(dir.string() + ": another run of case twice is writing there"),
            std::string::npos)
      << second.errors;
  EXPECT_EQ(second.output.find("step 1/"), std::string::npos) << "the refused run ran";
  EXPECT_TRUE(first.running()) << readFile(dir / "first.log");
  EXPECT_EQ(inodeOf(dir / "twice.nc.partial"), streaming);
  EXPECT_FALSE(fs::exists(dir / "twice.nc"));
  first.kill();

  // The lock goes with the process that held it: a run now starts (and is stopped early).
  BackgroundRun third("run " + file.string() + " -o " + dir.string(), dir / "third.log");
  EXPECT_TRUE(waitFor(dir / "third.log"));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_EQ(readFile(dir / "third.log").find("another run"), std::string::npos);
}

// SIGKILL: the streamed file stays readable up to its last flush (the static and modes steps'
// records are flushed when those steps end; time-step records at least once a second), and the
// earlier run's results are untouched.
TEST(OutputSafety, AKilledRunLeavesItsStreamedRecordsReadableAndTheEarlierResults) {
  const fs::path dir = scratch("killed");
  ASSERT_EQ(flexmoor("run " + writeCase(dir, "killed", demoCase("killed")).string() + " -o " +
                     dir.string())
                .exit_code,
            0);
  const std::string earlier = readFile(dir / "killed.nc");
  const fs::path file = writeCase(dir, "killed", longCase("killed"));
  BackgroundRun run("run " + file.string() + " -o " + dir.string(), dir / "run.log");
  ASSERT_TRUE(waitFor(dir / "killed.nc.partial")) << readFile(dir / "run.log");
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));  // a couple of flush intervals
  ASSERT_TRUE(run.running()) << readFile(dir / "run.log");
  run.kill();

  int partial = -1;
  ASSERT_EQ(nc_open((dir / "killed.nc.partial").c_str(), NC_NOWRITE, &partial), NC_NOERR);
  const std::vector<double> t = times(partial);
  nc_close(partial);
  ASSERT_GE(t.size(), 2u);  // the dynamic step's start, at t = 0 (pretension and modes: stage)
  EXPECT_EQ(t[0], 0.0);
  // Then every 5 ms time step, as far as it was flushed. The time is a sum of k steps, each
  // rounded to half an ulp of t at most: k eps t bounds the sum's error (1.6e-7 s at 380,000
  // records; it measures 1.8e-8 s there).
  for (size_t k = 1; k < t.size(); ++k)
    EXPECT_NEAR(t[k], 0.005 * k, 1e-12 + k * std::numeric_limits<double>::epsilon() * t[k]) << k;
  EXPECT_TRUE(readFile(dir / "killed.nc") == earlier) << "the earlier results changed";
}

// rename(2) replaces a planted link; the writers once opened its target (NC_CLOBBER, ofstream)
// and truncated it.
TEST(OutputSafety, LinksPlantedAtTheOutputsAreReplacedNotFollowed) {
  const fs::path dir = scratch("links");
  const fs::path outside = scratch("links-targets");
  const fs::path file = writeCase(outside, "linked", demoCase("linked"));
  for (const char* name :
       {"linked.nc", "linked.nc.partial", "linked-1.vtk", "linked-3.vtk", "linked.summary.json"}) {
    std::ofstream(outside / name) << "precious";
    fs::create_symlink(outside / name, dir / name);
  }
  const CliRun r = flexmoor("run " + file.string() + " -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* name : {"linked.nc", "linked-1.vtk", "linked-3.vtk", "linked.summary.json"}) {
    EXPECT_TRUE(readFile(outside / name) == "precious") << name << ": the link's target changed";
    EXPECT_FALSE(fs::is_symlink(dir / name)) << name;
    EXPECT_TRUE(fs::is_regular_file(dir / name)) << name;
  }
  EXPECT_TRUE(readFile(outside / "linked.nc.partial") == "precious");
  EXPECT_FALSE(fs::exists(dir / "linked.nc.partial"));
}

// A rerun with fewer steps removes the VTK files of the steps it no longer has (only this
// case's <case>-<n>.vtk), and nothing of the run is left under a temporary name.
TEST(OutputSafety, AFinishedRunLeavesExactlyItsOwnOutputs) {
  const fs::path dir = scratch("own-outputs");
  const fs::path cases = scratch("own-outputs-cases");
  ASSERT_EQ(
      flexmoor("run " + writeCase(cases, "own", demoCase("own")).string() + " -o " + dir.string())
          .exit_code,
      0);
  EXPECT_EQ(listing(dir), (std::set<std::string>{".own.lock", "own.nc", "own-1.vtk", "own-2.vtk",
                                                 "own-3.vtk", "own.summary.json"}));
  std::ofstream(dir / "other-2.vtk") << "another case's";
  std::ofstream(dir / "own-2.vtk.notes") << "the user's";

  std::string text = demoCase("own");  // the static step alone
  text = text.substr(0, text.find("  - modes:")) + text.substr(text.find("summary:"));
  text = std::regex_replace(text, std::regex("  omega_1:.*\n"), "");
  text = std::regex_replace(text, std::regex("  deflection:.*\n"), "");
  const CliRun r =
      flexmoor("run " + writeCase(cases, "own", text).string() + " -o " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(listing(dir),
            (std::set<std::string>{".own.lock", "own.nc", "own-1.vtk", "own.summary.json",
                                   "other-2.vtk", "own-2.vtk.notes"}));
}

// Without -o a case writes to results/<case>/; cases sharing one -o DIR keep a summary each.
TEST(OutputSafety, EachCaseHasItsOwnDirectoryByDefaultAndItsOwnSummaryInAShared) {
  const fs::path cwd = scratch("default-dir");
  const fs::path first = writeCase(cwd, "first", demoCase("first", 4));
  const fs::path second = writeCase(cwd, "second", demoCase("second", 4));
  const std::string binary = FLEXMOOR_BINARY;
  for (const fs::path& file : {first, second})
    ASSERT_EQ(std::system(("cd " + cwd.string() + " && " + binary + " run " + file.string() +
                           " >/dev/null 2>&1")
                              .c_str()),
              0);
  for (const char* name : {"first", "second"}) {
    const fs::path own = cwd / "results" / name;
    EXPECT_TRUE(fs::is_regular_file(own / (std::string(name) + ".nc"))) << name;
    EXPECT_NE(readFile(own / (std::string(name) + ".summary.json"))
                  .find("\"case\": \"" + std::string(name) + "\""),
              std::string::npos)
        << name;
  }

  const fs::path shared = cwd / "shared";
  for (const fs::path& file : {first, second})
    ASSERT_EQ(flexmoor("run " + file.string() + " -o " + shared.string()).exit_code, 0);
  EXPECT_NE(readFile(shared / "first.summary.json").find("\"case\": \"first\""), std::string::npos);
  EXPECT_NE(readFile(shared / "second.summary.json").find("\"case\": \"second\""),
            std::string::npos);
}

}  // namespace
