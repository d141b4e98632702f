// The fast path for the node table (apps/case/input/node_table.hpp): a table of plain
// `ID: [X, Y, Z]` lines is taken out of the text with every line number kept; anything else is
// left to yaml-cpp, so the reader's model and messages are the same either way.
#include "apps/case/input/node_table.hpp"

#include <gtest/gtest.h>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

TEST(NodeTable, PlainTableIsTakenOutKeepingLines) {
  std::string text =
      "units: SI\nnodes:\n  3: [1.5, -2, +3e2]  # a comment\n\n  1: [0, 0, 0]\nlines: []\n";
  const auto table = takeNodeTable(text);
  ASSERT_TRUE(table.has_value());
  EXPECT_EQ(table->key_line, 2);
  EXPECT_EQ(table->ids, (std::vector<int>{3, 1}));
  EXPECT_EQ(table->lines, (std::vector<int>{3, 5}));
  EXPECT_EQ(table->points[0], Eigen::Vector3d(1.5, -2.0, 300.0));  // exact: parsed, not computed
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 6);
  EXPECT_EQ(text.substr(text.rfind("lines")), "lines: []\n");
}

TEST(NodeTable, AnythingElseIsLeftToYaml) {
  for (std::string text :
       {"nodes:\n  1: [0 m, 0, 0]\n", "nodes:\n  1: [0, 0, 0]\n  1: [1, 0, 0]\n",
        "nodes:\n  1: {x: 0}\n", "nodes:\n  0: [0, 0, 0]\n", "nodes:\n  1: [nan, 0, 0]\n",
        "nodes: {1: [0, 0, 0]}\n", "nodes:\n  1: &a [0, 0, 0]\n"}) {
    const std::string before = text;
    EXPECT_FALSE(takeNodeTable(text).has_value()) << before;
    EXPECT_EQ(text, before);
  }
}

const char* kCase = R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2.0e11}
sections:
  wire: {material: steel, area: 1.0e-4}
nodes:
  20: [10, 0, 0]
  10: [0, 0, 0]
  15: [5, 0, 0]
elements:
  - {type: cable, nodes: [10, 15], section: wire}
  - {type: cable, nodes: [15, 20], section: wire}
supports:
  - {nodes: [10, 20], fix: [x, y, z]}
steps:
  - static: {}
)";

// The same case with a unit on one coordinate goes through yaml-cpp: the models agree exactly.
TEST(NodeTable, FastAndYamlPathsBuildTheSameModel) {
  const Case fast = readCase(test::writeCase("table-fast.yaml", kCase));
  std::string slow_text = kCase;
  slow_text.replace(slow_text.find("[5, 0, 0]"), 9, "[5 m, 0, 0]");
  const Case slow = readCase(test::writeCase("table-yaml.yaml", slow_text));
  EXPECT_EQ(fast.node_ids, (std::vector<int>{10, 15, 20}));
  EXPECT_EQ(fast.node_ids, slow.node_ids);
  EXPECT_EQ(fast.model->reference(), slow.model->reference());
}

// A mistake in a table (a repeated id) is reported by the ordinary path, with its line.
TEST(NodeTable, MistakesKeepTheirMessages) {
  std::string text = kCase;
  text.replace(text.find("  15: [5"), 4, "  20");
  const std::string file = test::writeCase("table-repeated.yaml", text);
  EXPECT_TRUE(test::anyContains(test::problems(file),
                                file + ":9: nodes.20: repeated key (first given on line 7)"))
      << test::joined(test::problems(file));
}

}  // namespace
}  // namespace flexmoor::app
