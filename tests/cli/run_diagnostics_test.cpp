// Where a run's words go: progress and the summary to stdout, diagnoses (a step that did not
// converge, where the last converged state is, a failure) to stderr, as exit-2 errors do.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <filesystem>
#include <regex>
#include <string>

#include "tests/support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

using flexmoor::test::CliRun;
using flexmoor::test::flexmoor;
using flexmoor::test::readFile;
using flexmoor::test::scratch;

// Example 1 with one relaxation step allowed: it cannot reach equilibrium (exit 3). The last
// stage record of diverge.nc, put in place, is the last converged state, named so.
TEST(RunDiagnostics, NonConvergenceIsDiagnosedOnStderrWithTheLastConvergedStateInPlace) {
  const fs::path dir = scratch("diverge-stderr");
  std::string text =
      readFile(fs::path(FLEXMOOR_SOURCE_DIR) / "cases/seed/ex1-suspended-cable-8xL2.yaml");
  text = std::regex_replace(text, std::regex("damping: 10000\\}"), "damping: 10000, max_steps: 1}");
  text = std::regex_replace(text, std::regex("name: ex1-suspended-cable-8xL2"), "name: diverge");
  const CliRun r = flexmoor::test::runText(dir, "diverge", text);
  ASSERT_EQ(r.exit_code, 3) << r.output;
  const std::string out = r.output.substr(0, r.output.size() - r.errors.size());
  EXPECT_NE(r.errors.find("did not converge"), std::string::npos) << r.errors;
  EXPECT_NE(r.errors.find("last converged state written to " + (dir / "diverge.nc").string()),
            std::string::npos)
      << r.errors;
  EXPECT_EQ(out.find("did not converge"), std::string::npos) << out;
  EXPECT_NE(out.find("step 1/"), std::string::npos) << out;  // progress stays on stdout
  EXPECT_FALSE(fs::exists(dir / "diverge.nc.partial"));

  int nc = -1, dim = -1, var = -1;
  size_t records = 0;
  ASSERT_EQ(nc_open((dir / "diverge.nc").c_str(), NC_NOWRITE, &nc), NC_NOERR);
  ASSERT_EQ(nc_inq_dimid(nc, "stage", &dim), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(nc, dim, &records), NC_NOERR);
  ASSERT_GE(records, 1u);
  size_t length = 0;  // name_strlen: the longest name the file holds
  ASSERT_EQ(nc_inq_dimid(nc, "name_strlen", &dim), NC_NOERR);
  ASSERT_EQ(nc_inq_dimlen(nc, dim, &length), NC_NOERR);
  std::string name(length, '\0');
  const size_t start[2] = {records - 1, 0}, count[2] = {1, length};
  ASSERT_EQ(nc_inq_varid(nc, "stage_step", &var), NC_NOERR);
  ASSERT_EQ(nc_get_vara_text(nc, var, start, count, name.data()), NC_NOERR);
  nc_close(nc);
  EXPECT_NE(name.find("(last converged)"), std::string::npos) << name;
}

}  // namespace
