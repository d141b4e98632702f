// Every named case's results select by time with xarray: each case under cases/ (not the study
// files) is run as it stands (the longest, the OC3 surge, takes 2 s: none needs shortening) and
// tests/cli/xarray_records_check.py opens its netCDF: `time` strictly increasing and unique,
// ds.sel(time=t) one record (exact at a stored time, method='nearest' with a 1e-9 s relative
// tolerance at that time rounded to 1e-9 s), `stage` likewise by step number, sel(end=1) the
// elements' first end.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

namespace fs = std::filesystem;

struct NamedCase {
  std::string case_name;
};

void PrintTo(const NamedCase& c, std::ostream* os) { *os << c.case_name; }

// The case files under cases/ (a study, with a top-level collect:, is not a case), by name.
std::vector<NamedCase> namedCases() {
  std::vector<NamedCase> cases;
  for (const auto& entry :
       fs::recursive_directory_iterator(fs::path(FLEXMOOR_SOURCE_DIR) / "cases")) {
    if (entry.path().extension() != ".yaml") continue;
    if (readFile(entry.path()).find("\ncollect:") != std::string::npos) continue;
    cases.push_back({entry.path().stem().string()});
  }
  std::sort(cases.begin(), cases.end(),
            [](const NamedCase& a, const NamedCase& b) { return a.case_name < b.case_name; });
  return cases;
}

class XarraySelectsRecords : public ::testing::TestWithParam<NamedCase> {};

TEST_P(XarraySelectsRecords, TimeIsStrictlyIncreasingAndSelects) {
  const std::string name = GetParam().case_name;
  const fs::path dir = scratch("xarray-records-" + name);
  const CliRun run = flexmoor("run " + name + " -o " + dir.string() + " --no-figure");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const CliRun check =
      command("/usr/bin/python3 " + std::string(FLEXMOOR_SOURCE_DIR) +
              "/tests/cli/xarray_records_check.py " + (dir / (name + ".nc")).string());
  EXPECT_EQ(check.exit_code, 0) << check.output;
  EXPECT_NE(check.output.find("xarray selects the records of"), std::string::npos) << check.output;
}

INSTANTIATE_TEST_SUITE_P(NamedCases, XarraySelectsRecords, ::testing::ValuesIn(namedCases()),
                         CaseParamName());

}  // namespace
}  // namespace flexmoor::test
