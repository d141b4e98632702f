// writeSummaryJson: the file reads back (yaml-cpp parses JSON) to the same doubles and strings.
#include "apps/output/summary_json.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

class SummaryJsonTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("flexmoor-summary-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    path_ = (dir_ / "summary.json").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  std::string path_;
};

TEST_F(SummaryJsonTest, ValuesRoundTripExactlyWithTheirUnits) {
  const std::vector<std::pair<std::string, double>> results = {
      {"centre_sag", 0.1},
      {"anchor_tension", -1234.5678901234567},
      {"tiny", 1.0e-300},
      {"huge", 6.02214076e23},
      {"whole", 42.0}};
  const std::vector<std::pair<std::string, std::string>> units = {
      {"centre_sag", "ft"}, {"anchor_tension", "lbf"}, {"tiny", "1"}};
  writeSummaryJson(path_, "ex1-suspended-cable", results, units);

  const YAML::Node json = YAML::LoadFile(path_);
  EXPECT_EQ(json["case"].as<std::string>(), "ex1-suspended-cable");
  ASSERT_EQ(json["results"].size(), results.size());
  for (const auto& [name, value] : results)
    EXPECT_EQ(json["results"][name].as<double>(), value) << name;
  ASSERT_EQ(json["units"].size(), units.size());
  for (const auto& [name, unit] : units) EXPECT_EQ(json["units"][name].as<std::string>(), unit);
}

TEST_F(SummaryJsonTest, NamesWithQuotesBackslashesAndControlCharactersAreEscaped) {
  const std::string name = "a \"quoted\" \\ name\twith\ncontrol\x01";
  writeSummaryJson(path_, "case \"q\"", {{name, 1.5}}, {{name, "lbf/ft^2"}});
  const YAML::Node json = YAML::LoadFile(path_);
  EXPECT_EQ(json["case"].as<std::string>(), "case \"q\"");
  EXPECT_EQ(json["results"][name].as<double>(), 1.5);
  EXPECT_EQ(json["units"][name].as<std::string>(), "lbf/ft^2");
}

TEST_F(SummaryJsonTest, EmptyResultsStillMakeAValidObject) {
  writeSummaryJson(path_, "nothing", {}, {});
  const YAML::Node json = YAML::LoadFile(path_);
  EXPECT_TRUE(json["results"].IsMap());
  EXPECT_EQ(json["results"].size(), 0u);
  EXPECT_TRUE(json["units"].IsMap());
}

TEST_F(SummaryJsonTest, NaNIsRefusedBeforeAnythingIsWritten) {
  try {
    writeSummaryJson(path_, "c", {{"ok", 1.0}, {"sag", std::numeric_limits<double>::quiet_NaN()}},
                     {});
    FAIL() << "a NaN was written";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("\"sag\" is NaN"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path_));
}

TEST_F(SummaryJsonTest, InfinityIsRefused) {
  EXPECT_THROW(writeSummaryJson(path_, "c", {{"t", -std::numeric_limits<double>::infinity()}}, {}),
               std::runtime_error);
}

TEST_F(SummaryJsonTest, DuplicateResultNameIsRefused) {
  EXPECT_THROW(writeSummaryJson(path_, "c", {{"t", 1.0}, {"t", 2.0}}, {}), std::runtime_error);
}

}  // namespace
}  // namespace flexmoor::app
