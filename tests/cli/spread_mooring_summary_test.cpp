// The default summary of scenario: spread_mooring says what each value is: the state closing the
// static step (_static_k: the fairlead tension is the line's pretension) and, with a dynamic
// step, extremes over it (_max_k, _min_k). OC3-Hywind's surge case without its own summary, cut
// to 5 s, against the same quantities written out by element and node number with their step
// (step 1, the static equilibrium; stat: over step 2, the surge): equal to the bit (the same
// evaluation of the same states; tolerance 0).
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "tests/support/cli_run.hpp"

namespace flexmoor::test {
namespace {

std::string surgeWithoutSummary() {
  std::string text =
      readFile(std::string(FLEXMOOR_SOURCE_DIR) + "/cases/ocean/oc3-hywind-surge.yaml");
  const size_t summary = text.find("\nsummary:");
  EXPECT_NE(summary, std::string::npos);
  text = text.substr(0, summary + 1);
  text = std::regex_replace(text, std::regex("steps: 6000"), "steps: 50");  // 5 s
  return text;
}

// Line k of OC3's (12 elements each, no point masses before them): its first and last element.
std::string explicitSummary() {
  std::string s = "summary:\n";
  for (int k = 1; k <= 3; ++k) {
    const std::string n = std::to_string(k), first = std::to_string(12 * (k - 1) + 1),
                      last = std::to_string(12 * k), line = "line_" + n;
    const auto add = [&](const std::string& key, const std::string& body) {
      s += "  " + key + "_" + n + ": {" + body + "}\n";
    };
    add("fairlead_tension_static",
        "quantity: end_tension, element: " + last + ", end: last, step: 1");
    add("fairlead_horizontal_static",
        "quantity: reaction_horizontal, node: " + line + ".end, step: 1");
    add("fairlead_vertical_static", "quantity: reaction_z, node: " + line + ".end, step: 1");
    add("anchor_tension_static",
        "quantity: end_tension, element: " + first + ", end: first, step: 1");
    add("anchor_horizontal_static",
        "quantity: reaction_horizontal, node: " + line + ".start, step: 1");
    add("anchor_vertical_static",
        "quantity: reaction_z, node: " + line + ".start, scale: -1, step: 1");
    add("length_on_seabed_static", "quantity: length_on_seabed, line: " + line + ", step: 1");
    add("fairlead_tension_max",
        "quantity: end_tension, element: " + last + ", end: last, step: 2, stat: max");
    add("fairlead_tension_min",
        "quantity: end_tension, element: " + last + ", end: last, step: 2, stat: min");
    add("anchor_tension_max",
        "quantity: end_tension, element: " + first + ", end: first, step: 2, stat: max");
    add("anchor_vertical_max",
        "quantity: reaction_z, node: " + line + ".start, scale: -1, step: 2, stat: max");
  }
  return s;
}

TEST(SpreadMooringSummary, DefaultNamesAreTheStaticStateAndTheDynamicExtremes) {
  const std::string by_default = runCaseText("oc3-default-summary", surgeWithoutSummary());
  const std::string written =
      runCaseText("oc3-written-summary", surgeWithoutSummary() + explicitSummary());
  int compared = 0;
  for (int k = 1; k <= 3; ++k)
    for (const char* key :
         {"fairlead_tension_static", "fairlead_horizontal_static", "fairlead_vertical_static",
          "anchor_tension_static", "anchor_horizontal_static", "anchor_vertical_static",
          "length_on_seabed_static", "fairlead_tension_max", "fairlead_tension_min",
          "anchor_tension_max", "anchor_vertical_max"}) {
      const std::string name = std::string(key) + "_" + std::to_string(k);
      const double value = summaryValue(by_default, name);
      ASSERT_TRUE(std::isfinite(value)) << name << "\n" << by_default;
      EXPECT_EQ(value, summaryValue(written, name)) << name;
      ++compared;
    }
  EXPECT_EQ(compared, 33);
  // What the names promise: the surge swings the fairlead tension about its pretension.
  for (const std::string n : {"1", "2", "3"}) {
    EXPECT_GT(summaryValue(by_default, "fairlead_tension_max_" + n),
              summaryValue(by_default, "fairlead_tension_static_" + n));
    EXPECT_LT(summaryValue(by_default, "fairlead_tension_min_" + n),
              summaryValue(by_default, "fairlead_tension_static_" + n));
  }
  EXPECT_EQ(by_default.find("\"fairlead_tension_1\""), std::string::npos) << by_default;
}

}  // namespace
}  // namespace flexmoor::test
