// Outputs put in place atomically (atomic_output.hpp), the lock of a case's outputs
// (output_lock.hpp) and which files of a directory are a case's stale outputs (case_outputs.hpp).
#include "apps/output/atomic_output.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "apps/output/output_lock.hpp"
#include "apps/run/case_outputs.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

class AtomicOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexmoor-atomic-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::set<std::string> listing() const {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
      names.insert(entry.path().filename().string());
    return names;
  }

  fs::path dir_;
};

std::string contentOf(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST_F(AtomicOutputTest, WritesTheTextAndLeavesNoTemporaryFile) {
  const fs::path path = dir_ / "case.summary.json";
  writeFileAtomically(path.string(), "first");
  writeFileAtomically(path.string(), "second, longer");
  EXPECT_EQ(contentOf(path), "second, longer");
  EXPECT_EQ(listing(), (std::set<std::string>{"case.summary.json"}));
}

// std::ofstream(path) opens a planted link's target and truncates it.
TEST_F(AtomicOutputTest, ASymbolicLinkAtThePathIsReplacedNotFollowed) {
  const fs::path target = dir_ / "precious.txt", path = dir_ / "case-1.vtk";
  std::ofstream(target) << "precious";
  fs::create_symlink(target, path);
  writeFileAtomically(path.string(), "vtk");
  EXPECT_EQ(contentOf(target), "precious");
  EXPECT_FALSE(fs::is_symlink(path));
  EXPECT_EQ(contentOf(path), "vtk");
}

// A reader that has the old file open reads the old file to its end.
TEST_F(AtomicOutputTest, AReaderOfTheOldFileKeepsIt) {
  const fs::path path = dir_ / "case.summary.json";
  writeFileAtomically(path.string(), "old results");
  std::ifstream reader(path);
  writeFileAtomically(path.string(), "new");
  std::stringstream s;
  s << reader.rdbuf();
  EXPECT_EQ(s.str(), "old results");
  EXPECT_EQ(contentOf(path), "new");
}

// A directory in the way: the rename fails, the error names the path, nothing is left behind.
TEST_F(AtomicOutputTest, AFailureLeavesThePathAsItWasAndNoTemporaryFile) {
  const fs::path path = dir_ / "case-2.vtk";
  fs::create_directories(path / "inside");
  try {
    writeFileAtomically(path.string(), "vtk");
    FAIL() << "wrote over a directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(path / "inside"));
  EXPECT_EQ(listing(), (std::set<std::string>{"case-2.vtk"}));
}

TEST_F(AtomicOutputTest, MoveIntoPlaceReplacesALinkAndRemoveEntryRemovesOnlyTheLink) {
  const fs::path target = dir_ / "precious.txt", path = dir_ / "case.nc";
  std::ofstream(target) << "precious";
  fs::create_symlink(target, path);
  std::ofstream(dir_ / "case.nc.partial") << "results";
  moveIntoPlace((dir_ / "case.nc.partial").string(), path.string());
  EXPECT_EQ(contentOf(path), "results");
  EXPECT_EQ(contentOf(target), "precious");
  fs::create_symlink(target, dir_ / "link");
  removeEntry((dir_ / "link").string());
  removeEntry((dir_ / "absent").string());  // nothing there: nothing to do
  EXPECT_EQ(listing(), (std::set<std::string>{"case.nc", "precious.txt"}));
}

// flock(2) locks conflict between open files even within one process, so a second OutputLock
// here stands for a second run.
TEST_F(AtomicOutputTest, ASecondLockOfTheSameFileIsRefusedUntilTheFirstIsReleased) {
  const std::string path = (dir_ / ".case.lock").string();
  {
    const OutputLock first(path, "busy");
    try {
      const OutputLock second(path, "busy");
      FAIL() << "locked twice";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "busy");
    }
  }
  EXPECT_NO_THROW(OutputLock(path, "busy"));
}

// Only <case>-<n>.vtk (n not written) and the temporaries of an interrupted atomic write of the
// case's files are stale; other cases' files, other names and directories are not.
TEST_F(AtomicOutputTest, StaleOutputsAreOnlyThoseOfTheCase) {
  for (const char* name :
       {"a-1.vtk", "a-2.vtk", "a-10.vtk", "a-01.vtk", "a-x.vtk", "a-1-2.vtk", "ab-3.vtk", "a.nc",
        "a-3.vtk.bak", "b-2.vtk", ".a-4.vtk.tmp-123-0", ".a.summary.json.tmp-9-1",
        ".b.summary.json.tmp-9-1", ".a.nc.tmp-9-1", "a.summary.json"})
    std::ofstream(dir_ / name) << name;
  fs::create_directories(dir_ / "a-5.vtk");
  CaseOutputs(dir_.string(), "a").removeStale({1});
  EXPECT_EQ(listing(),
            (std::set<std::string>{"a-1.vtk", "a-01.vtk", "a-x.vtk", "a-1-2.vtk", "ab-3.vtk",
                                   "a.nc", "a-3.vtk.bak", "b-2.vtk", ".b.summary.json.tmp-9-1",
                                   ".a.nc.tmp-9-1", "a.summary.json", "a-5.vtk"}));
}

TEST(CaseOutputs, EveryFileIsNamedAfterTheCase) {
  const CaseOutputs files("out", "ex1");
  EXPECT_EQ(files.netcdf(), "out/ex1.nc");
  EXPECT_EQ(files.partialNetcdf(), "out/ex1.nc.partial");
  EXPECT_EQ(files.vtk(3), "out/ex1-3.vtk");
  EXPECT_EQ(files.summary(), "out/ex1.summary.json");
  EXPECT_EQ(files.lock(), "out/.ex1.lock");
  EXPECT_EQ(defaultOutputDirectory("ex1"), "results/ex1");
}

}  // namespace
}  // namespace flexmoor::app
