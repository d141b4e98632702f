// Places on a named line in what a case reports (apps/case/read/line_refs.cpp): summary: entries
// and figure: series by `line: NAME` with `end:` (start, end, first, last, 1, 2; anchor and
// fairlead of a mooring line, `anchor:`), `node: K` or `element: K`; LINE.anchor and LINE.fairlead
// as node references; element ends as first, last, 1 or 2. Each form must resolve to the very node,
// element and end its element-number form names.
#include <gtest/gtest.h>

#include <string>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::app {
namespace {

// An explicit cable (element 1, nodes 1-2) first, then "moor", a mooring line from its anchor
// at the origin to its fairlead, 4 L3 elements (2 to 5, nodes 3...11 with node 1 as its start),
// then "tail" (element 6), a line on no anchor continuing from moor.fairlead.
std::string linesCase(const std::string& summary, const std::string& figure = "") {
  return R"(units: SI
materials:
  steel: {type: linear_elastic, E: 2e11 Pa}
sections:
  wire: {material: steel, area: 1e-4 m^2, density: 7850 kg/m^3}
nodes:
  1: [0, 0, 0]
  2: [0, 0, -5 m]
lines:
  - {name: moor, start_node: 1, to: [40 m, 0, 0], elements: 4, order: 3, section: wire,
     anchor: start}
  - {name: tail, start_node: moor.fairlead, to: [50 m, 0, 0], elements: 1, order: 2,
     section: wire}
elements:
  - {type: cable, nodes: [2, 1], section: wire}
supports:
  - {node: moor.anchor, fix: [x, y, z]}
  - {node: 2, fix: [x, y, z]}
  - {node: tail.end, fix: [x, y, z], displacement: [0.01 m, 0, 0]}
  - {nodes: all, fix: [y]}
steps:
  - static: {name: pull}
summary:
)" + summary +
         figure;
}

const SummarySpec& spec(const Case& c, const std::string& name) {
  for (const SummarySpec& s : c.summary)
    if (s.name == name) return s;
  throw std::runtime_error("no summary quantity " + name);
}

TEST(CaseReaderLineRefs, LineEndsElementsAndNodesAreTheNumberedOnes) {
  const Case c = readCase(test::writeCase("line-refs.yaml", linesCase(R"(
  fairlead: {quantity: end_tension, line: moor, end: fairlead}
  fairlead_numbered: {quantity: end_tension, element: 5, end: last}
  anchor: {quantity: end_tension, line: moor, end: anchor}
  anchor_numbered: {quantity: end_tension, element: 2, end: first}
  start: {quantity: end_tension, line: tail, end: start}
  third: {quantity: end_tension, line: moor, element: 3, end: 2}
  third_numbered: {quantity: end_tension, element: 4, end: last}
  dotted: {quantity: end_tension, element: moor.3, end: last}
  node_end: {quantity: reaction_x, line: moor, end: anchor}
  node_first: {quantity: reaction_x, line: moor, end: first}
  node_k: {quantity: position_z, line: moor, node: 5}
  node_fairlead: {quantity: position_z, node: moor.fairlead}
  node_tail_end: {quantity: reaction_x, line: tail, end: 2}
)")));
  const auto at = [&](const std::string& name) {
    const SummarySpec& s = spec(c, name);
    return std::pair{s.element, s.end};
  };
  EXPECT_EQ(at("fairlead"), (std::pair{4, 1}));
  EXPECT_EQ(at("fairlead"), at("fairlead_numbered"));
  EXPECT_EQ(at("anchor"), (std::pair{1, 0}));
  EXPECT_EQ(at("anchor"), at("anchor_numbered"));
  EXPECT_EQ(at("start"), (std::pair{5, 0}));
  EXPECT_EQ(at("third"), (std::pair{3, 1}));
  EXPECT_EQ(at("third"), at("third_numbered"));
  EXPECT_EQ(at("dotted"), at("third_numbered"));
  const std::vector<int>& moor = c.lines.at("moor");
  ASSERT_EQ(moor.size(), 9u);
  EXPECT_EQ(spec(c, "node_end").node, moor.front());
  EXPECT_EQ(spec(c, "node_first").node, moor.front());
  EXPECT_EQ(spec(c, "node_k").node, moor[4]);
  EXPECT_EQ(spec(c, "node_fairlead").node, moor.back());
  EXPECT_EQ(spec(c, "node_tail_end").node, c.lines.at("tail").back());
  ASSERT_EQ(c.named_lines.size(), 2u);
  EXPECT_EQ(c.named_lines[0].name, "moor");
  EXPECT_EQ(c.named_lines[0].anchor, CaseLine::Anchor::Start);
  EXPECT_EQ(c.named_lines[0].elements, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(c.named_lines[1].anchor, CaseLine::Anchor::None);
}

// Element ends read the same as first | last and 1 | 2 in summaries and figures alike.
TEST(CaseReaderLineRefs, ElementEndsAreFirstLastOneOrTwo) {
  const Case c = readCase(test::writeCase("ends.yaml", linesCase(R"(
  one: {quantity: end_tension, element: 3, end: 1}
  first: {quantity: end_tension, element: 3, end: first}
  two: {quantity: end_tension, element: 3, end: 2}
  last: {quantity: end_tension, element: 3, end: last}
)",
                                                                 R"(figure:
  series:
    - {quantity: tension_end, element: 3, end: last}
    - {quantity: tension_end, element: 3, end: 1}
    - {quantity: tension_end, line: moor, end: fairlead}
    - {quantity: tension_end, line: moor, element: 2, end: first}
    - {quantity: position_z, line: moor, end: fairlead}
    - {quantity: position_x, line: moor, node: 3}
)")));
  EXPECT_EQ(spec(c, "one").end, 0);
  EXPECT_EQ(spec(c, "first").end, 0);
  EXPECT_EQ(spec(c, "two").end, 1);
  EXPECT_EQ(spec(c, "last").end, 1);
  ASSERT_TRUE(c.figure);
  const std::vector<int>& moor = c.lines.at("moor");
  EXPECT_EQ(c.figure->series,
            (std::vector<std::string>{"tension_end@element=3,end=2", "tension_end@element=3,end=1",
                                      "tension_end@element=5,end=2", "tension_end@element=3,end=1",
                                      "position_z@node=" + std::to_string(moor.back() + 1),
                                      "position_x@node=" + std::to_string(moor[2] + 1)}));
}

// Wrong places are named with what exists.
TEST(CaseReaderLineRefs, WrongPlacesNameWhatExists) {
  const std::vector<std::string> m = test::problems(test::writeCase("bad-refs.yaml", linesCase(R"(
  a: {quantity: end_tension, line: line_9, end: fairlead}
  b: {quantity: end_tension, line: tail, end: fairlead}
  c: {quantity: end_tension, line: moor, element: 5, end: last}
  d: {quantity: position_x, line: moor, node: 10}
  e: {quantity: end_tension, element: moor.end, end: last}
  f: {quantity: end_tension, element: 3, end: middle}
  g: {quantity: position_x, node: 1, end: first}
  h: {quantity: position_x, line: moor}
)")));
  const std::string all = test::joined(m);
  EXPECT_TRUE(test::anyContains(m,
                                "bad-refs.yaml:25: summary.a.line: no line 'line_9' (got "
                                "'line_9', expected one of the case's lines: moor, tail)"))
      << all;
  EXPECT_TRUE(test::anyContains(m,
                                "bad-refs.yaml:26: summary.b.end: line 'tail' has no "
                                "fairlead (got 'fairlead', expected start, end, first"))
      << all;
  EXPECT_TRUE(test::anyContains(m,
                                "bad-refs.yaml:27: summary.c.element: no such element of line "
                                "'moor' (got '5', expected 1 to 4"))
      << all;
  EXPECT_TRUE(test::anyContains(m,
                                "bad-refs.yaml:28: summary.d.node: no such node of line "
                                "'moor' (got '10', expected 1 to 9"))
      << all;
  EXPECT_TRUE(test::anyContains(m,
                                "bad-refs.yaml:29: summary.e.element: not an element (got "
                                "'moor.end', a place on line 'moor'"))
      << all;
  EXPECT_TRUE(test::anyContains(m,
                                "bad-refs.yaml:30: summary.f.end: not an end of an element "
                                "(got 'middle', expected first or 1"))
      << all;
  EXPECT_TRUE(test::anyContains(m,
                                "bad-refs.yaml:31: summary.g.end: not used by position_x "
                                "without line:"))
      << all;
  EXPECT_TRUE(test::anyContains(m,
                                "bad-refs.yaml:32: summary.h: missing key 'end' (or 'node: "
                                "K') with line:"))
      << all;
}

}  // namespace
}  // namespace flexmoor::app
