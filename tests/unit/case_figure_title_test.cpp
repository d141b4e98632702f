// A shipped case's figure title names only nodes that its series draw, by the numbers the
// figure's legends give (the netCDF's 1-based `node`, which the figure's series select:
// apps/case/read/read_figure.cpp), not by another numbering such as the dissertation's.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "apps/case/case_reader.hpp"
#include "apps/study/study_reader.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

// The node numbers a title names: "node 41", "nodes 16, 31", "nodes 1, 7 and 10".
std::set<int> nodesNamed(const std::string& title) {
  std::set<int> named;
  const std::regex phrase(R"(\bnodes?\s+(\d+(\s*(,|and|, and)\s*\d+)*))");
  const std::regex number(R"(\d+)");
  for (std::sregex_iterator p(title.begin(), title.end(), phrase), end; p != end; ++p) {
    const std::string list = (*p)[1];
    for (std::sregex_iterator n(list.begin(), list.end(), number); n != end; ++n)
      named.insert(std::stoi(n->str()));
  }
  return named;
}

// The nodes a figure's series select ("displacement_x@node=41").
std::set<int> nodesDrawn(const FigureSpec& figure) {
  std::set<int> drawn;
  const std::regex node(R"(@node=(\d+))");
  std::smatch m;
  for (const std::string& s : figure.series)
    if (std::regex_search(s, m, node)) drawn.insert(std::stoi(m[1]));
  return drawn;
}

TEST(CaseFigureTitle, NodesNamedAreRead) {
  EXPECT_EQ(nodesNamed("Example 9, displacement histories of nodes 1, 7, 4, 10 and a tension"),
            (std::set<int>{1, 4, 7, 10}));
  EXPECT_EQ(nodesNamed("top (node 41), sides (nodes 16, 31 and 2)"),
            (std::set<int>{2, 16, 31, 41}));
  EXPECT_TRUE(nodesNamed("Example 8, buoy released at t = 0").empty());
}

TEST(CaseFigureTitle, EveryShippedTitleNamesTheNodesItsLegendsGive) {
  int titled = 0;
  for (const auto& entry :
       fs::recursive_directory_iterator(fs::path(FLEXMOOR_SOURCE_DIR) / "cases")) {
    const std::string path = entry.path().string();
    if (entry.path().extension() != ".yaml" || isStudyFile(path)) continue;
    const Case c = readCase(path);
    if (!c.figure) continue;
    const std::set<int> named = nodesNamed(c.figure->title.empty() ? c.title : c.figure->title);
    const std::set<int> drawn = nodesDrawn(*c.figure);
    for (int n : named)
      EXPECT_TRUE(drawn.count(n)) << path << ": the figure's title names node " << n
                                  << ", which none of its series draws";
    titled += named.empty() ? 0 : 1;
  }
  EXPECT_GE(titled, 1);  // Example 9's
}

}  // namespace
}  // namespace flexmoor::app
