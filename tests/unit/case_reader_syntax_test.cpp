// YAML text that yaml-cpp lets through or words poorly: an unclosed quote, nesting
// deep enough to exhaust the parser, aliases that expand without bound. Each gives one message
// with its line, and nothing else of the file is read.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "apps/case/case_reader.hpp"
#include "apps/case/input/yaml_load.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

using test::joined;
using test::problems;
using test::writeCase;

// A valid case: a wire pulled along its axis.
const std::string kWire = R"(units: SI
materials:
  steel: {type: linear_elastic, E: 200 GPa}
sections:
  wire: {material: steel, area: 1 cm^2, density: 7850 kg/m^3}
lines:
  - {name: wire, from: [0, 0, 0], to: [10, 0, 0], elements: 2, order: 2, section: wire}
supports:
  - {nodes: all, fix: [y, z]}
  - {node: wire.start, fix: [x]}
loads:
  nodal: [{node: wire.end, force: [1000 N, 0, 0]}]
steps:
  - static: {}
)";

// [[[ ... ]]] with `depth` brackets, as the value of key `a`.
std::string nested(int depth) {
  return "a: " + std::string(depth, '[') + std::string(depth, ']') + "\n";
}

// The classic "billion laughs": lists of nine aliases, each to the list before.
std::string aliasBomb() {
  std::string text = "units: SI\nl0: &l0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n";
  for (int k = 1; k <= 9; ++k) {
    const std::string prev = "*l" + std::to_string(k - 1);
    text += "l" + std::to_string(k) + ": &l" + std::to_string(k) + " [";
    for (int i = 0; i < 9; ++i) text += (i ? ", " : "") + prev;
    text += "]\n";
  }
  return text + "steps: *l9\n";
}

// yaml-cpp reads an unclosed quote to the end of the file; the case name was that whole text.
TEST(CaseReaderSyntax, UnclosedDoubleQuoteIsReportedAtItsOpeningLine) {
  const std::vector<std::string> m =
      problems(writeCase("dquote.yaml", "units: SI\ntitle: a test\nname: \"wire\n" + kWire));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("dquote.yaml:3: the string quoted with \" here is never closed"),
            std::string::npos)
      << m[0];
}

TEST(CaseReaderSyntax, UnclosedSingleQuoteIsReportedAtItsOpeningLine) {
  const std::vector<std::string> m =
      problems(writeCase("squote.yaml", kWire + "title: 'it''s a\n  wire\n"));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("squote.yaml:15: the string quoted with ' here is never closed"),
            std::string::npos)
      << m[0];
}

// yaml-cpp's positions do not count a UTF-8 byte-order mark; nor do those of the check.
TEST(CaseReaderSyntax, UnclosedQuoteAfterAByteOrderMarkIsReported) {
  const std::vector<std::string> m = problems(writeCase("bom.yaml",
                                                        "\xEF\xBB\xBFunits: SI\ntitle: \"c\xC3\xA2"
                                                        "ble\n" +
                                                            kWire));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("bom.yaml:2: the string quoted with \" here is never closed"),
            std::string::npos)
      << m[0];
}

// In a flow map (the style of most cases) yaml-cpp failed at the end of the file instead, with
// "end of map flow not found".
TEST(CaseReaderSyntax, UnclosedQuoteInAFlowMapIsReportedAtItsOpeningLine) {
  std::string text = kWire;
  text.replace(text.find("{name: wire,"), 12, "{name: \"wire,");
  const std::vector<std::string> m = problems(writeCase("flow.yaml", text));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("flow.yaml:7: the string quoted with \" here is never closed"),
            std::string::npos)
      << m[0];
}

// Closed quotes, escaped quotes, quotes over two lines and apostrophes in plain text are fine.
TEST(CaseReaderSyntax, ClosedQuotesAreRead) {
  const Case a = readCase(writeCase("quotes.yaml", kWire + "title: \"say \\\"hi\\\" to\n  it\"\n"));
  EXPECT_EQ(a.title, "say \"hi\" to it");
  const Case b = readCase(writeCase("quotes.yaml", "title: 'it''s'\n" + kWire));
  EXPECT_EQ(b.title, "it's");
  const Case c = readCase(writeCase("quotes.yaml", "title: Bob's \"wire\"\n" + kWire));
  EXPECT_EQ(c.title, "Bob's \"wire\"");
}

// Levels count the top map: `a: [[...]]` with 255 brackets is 256 levels, the most allowed.
TEST(CaseReaderSyntax, NestingDeeperThanTheLimitIsRefusedWithItsLine) {
  const std::vector<std::string> at_limit =
      problems(writeCase("deep255.yaml", kWire + nested(kMaxNesting - 1)));
  ASSERT_EQ(at_limit.size(), 1u) << joined(at_limit);
  EXPECT_NE(at_limit[0].find("deep255.yaml:15: unknown key 'a'"), std::string::npos) << at_limit[0];

  const std::vector<std::string> over =
      problems(writeCase("deep256.yaml", kWire + nested(kMaxNesting)));
  ASSERT_EQ(over.size(), 1u) << joined(over);
  EXPECT_NE(over[0].find("deep256.yaml:15: lists and maps nested deeper than 256 levels"),
            std::string::npos)
      << over[0];
}

// 100,000 brackets: yaml-cpp's own guard (at 500 levels) said only "bad file".
TEST(CaseReaderSyntax, HundredThousandNestedBracketsAreRefusedWithItsLine) {
  const std::vector<std::string> m =
      problems(writeCase("deep100k.yaml", "units: SI\n" + nested(100000)));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("deep100k.yaml:2: lists and maps nested deeper than 256 levels"),
            std::string::npos)
      << m[0];
}

// l9 is 9^10 = 3.5e9 scalars from a file of 561 characters. The walk stops at the budget, in the
// first top-level entry whose values pass it: l0..l5 hold 672,609 values with their keys and
// lists, l6 alone 5,380,840.
TEST(CaseReaderSyntax, AliasBombIsRefusedAtTheBudget) {
  const std::string text = aliasBomb();
  const std::vector<std::string> m = problems(writeCase("bomb.yaml", text));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  const std::string expected = "bomb.yaml:8: l6: YAML aliases expand to more than " +
                               std::to_string(aliasBudget(text.size())) +
                               " values (an alias bomb?)";
  EXPECT_NE(m[0].find(expected), std::string::npos) << m[0];
}

// Block maps nested by indentation: the line is where the 257th level opens, whether the
// reader's walk (300 levels) or yaml-cpp's guard at 500 (1,000 levels) stops the nesting.
TEST(CaseReaderSyntax, NestingByIndentationIsRefusedWhereItPassesTheLimit) {
  for (int levels : {300, 1000}) {
    std::string text = "units: SI\n";
    for (int i = 0; i < levels; ++i) text += std::string(i, ' ') + "k:\n";
    const std::vector<std::string> m = problems(writeCase("indent.yaml", text));
    ASSERT_EQ(m.size(), 1u) << joined(m);
    // The top map opens on line 1; the map of level L on line L + 1.
    EXPECT_NE(m[0].find("indent.yaml:258: lists and maps nested deeper than 256 levels"),
              std::string::npos)
        << levels << ": " << m[0];
  }
}

// An alias inside its own anchor is a cycle: a reader walking it would never end. It nests
// without end, so the nesting limit stops it, at the anchor's line.
TEST(CaseReaderSyntax, SelfReferentialAliasIsRefused) {
  const std::vector<std::string> m =
      problems(writeCase("cycle.yaml", kWire + "node_sets:\n  loop: &loop [1, *loop]\n"));
  ASSERT_EQ(m.size(), 1u) << joined(m);
  EXPECT_NE(m[0].find("cycle.yaml:16: lists and maps nested deeper than 256 levels"),
            std::string::npos)
      << m[0];
}

// Reusing an anchor as YAML means it is still fine.
TEST(CaseReaderSyntax, ReusedAnchorsAreRead) {
  std::string text = kWire;
  text.replace(text.find("  wire: {material"), 17, "  spare: &wire {material");
  text.insert(text.find("lines:"), "  wire: *wire\n");
  const Case c = readCase(writeCase("anchors.yaml", text));
  EXPECT_EQ(c.model->elementCount(), 2);
}

}  // namespace
}  // namespace flexmoor::app
