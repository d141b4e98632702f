// Files of time series for prescribed motions (apps/case/read/motion_file.hpp): comma-separated
// with a header, whitespace- and tab-separated with or without one, columns by name or by 1-based
// number, and each problem at its line of the file.
#include "apps/case/read/motion_file.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace flexmoor::app {
namespace {

MotionSeries read(const std::string& text, const MotionColumn& time, const MotionColumn& value) {
  std::istringstream in(text);
  return readMotionColumns(in, time, value);
}

void expectSeries(const MotionSeries& s, const std::vector<double>& times,
                  const std::vector<double>& values) {
  ASSERT_FALSE(s.problem) << s.problem->line << ": " << s.problem->what;
  EXPECT_EQ(s.times, times);
  EXPECT_EQ(s.values, values);
}

void expectProblem(const MotionSeries& s, int line, const std::string& what) {
  ASSERT_TRUE(s.problem);
  EXPECT_EQ(s.problem->line, line);
  EXPECT_EQ(s.problem->what, what);
  EXPECT_TRUE(s.times.empty());
}

TEST(MotionFile, CommaSeparatedWithAHeaderByNameOrNumber) {
  const std::string csv = "# platform\n\ntime, surge, heave\n0, 1.5, -2\n0.5, 2.5, -3\n";
  expectSeries(read(csv, {}, MotionColumn::named("heave")), {0.0, 0.5}, {-2.0, -3.0});
  expectSeries(read(csv, {}, MotionColumn::numbered(2)), {0.0, 0.5}, {1.5, 2.5});
  expectSeries(read(csv, MotionColumn::named("surge"), MotionColumn::numbered(1)), {1.5, 2.5},
               {0.0, 0.5});
}

TEST(MotionFile, TabAndSpaceSeparatedWithoutAHeaderByNumber) {
  const std::string tabs = "0.0\t0.1\t-1e-3\n  0.05\t0.2\t 2E-3\r\n0.1\t\t0.3\t3e-3\n";
  expectSeries(read(tabs, {}, MotionColumn::numbered(3)), {0.0, 0.05, 0.1}, {-1e-3, 2e-3, 3e-3});
  expectSeries(read(tabs, MotionColumn::numbered(2), MotionColumn::numbered(1)), {0.1, 0.2, 0.3},
               {0.0, 0.05, 0.1});
  const std::string spaces = "# MoorDyn-style\n1 10 100\n2   20   200\n";
  expectSeries(read(spaces, {}, MotionColumn::numbered(2)), {1.0, 2.0}, {10.0, 20.0});
}

TEST(MotionFile, WhitespaceSeparatedWithAHeader) {
  const std::string text = "Time\tPtfmSurge\tPtfmHeave\n0\t1\t2\n1\t3\t4\n";
  expectSeries(read(text, MotionColumn::named("Time"), MotionColumn::named("PtfmHeave")),
               {0.0, 1.0}, {2.0, 4.0});
  expectProblem(read(text, {}, MotionColumn::named("PtfmHeave")), 1,
                "no column 'time' (got Time, PtfmSurge, PtfmHeave)");
}

TEST(MotionFile, ProblemsAreAtTheirLine) {
  const std::string headerless = "# no header\n0 1\n1 2\n";
  expectProblem(read(headerless, {}, MotionColumn::named("surge")), 2,
                "no line of column names to find 'surge' in (the first line is numbers; name "
                "the column by its number, 1-based, like column: 2)");
  expectProblem(read("time, surge\n0, 1\n", {}, MotionColumn::named("sway")), 1,
                "no column 'sway' (got time, surge)");
  expectProblem(read("time, surge\n0, 1\n", {}, MotionColumn::numbered(3)), 1,
                "no column 3 (the header names 2: time, surge)");
  expectProblem(read("0 1\n\n1 2\n2 x\n", {}, MotionColumn::numbered(2)), 4,
                "not a number (got 'x' in column 2)");
  expectProblem(read("time, surge\n0, 1\n1, nan\n", {}, MotionColumn::named("surge")), 3,
                "not a number (got 'nan' in column surge)");
  expectProblem(read("0 1 2\n1 2\n", {}, MotionColumn::numbered(3)), 2,
                "too few fields (got 2, expected column 3)");
  expectProblem(read("# only a comment\n\n", {}, MotionColumn::numbered(2)), 2,
                "no rows (expected lines of numbers: a time and the column's value)");
  // A header and no rows: read, the spline's reader says there are no samples.
  expectSeries(read("time, surge\n", {}, MotionColumn::named("surge")), {}, {});
}

}  // namespace
}  // namespace flexmoor::app
