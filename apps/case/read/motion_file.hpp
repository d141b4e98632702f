#pragma once
// A file of time series for a prescribed motion (read_motion.hpp), as users have them: comma-
// separated with a line of column names (a spreadsheet's CSV), or whitespace- or tab-separated
// with or without one (MoorDyn's and OpenFAST's motion files have none).
//
// Blank lines and lines starting with '#' are skipped. The first other line decides the
// separator (a comma in it: commas; else runs of spaces and tabs) and is the header when any of
// its fields is not a number; every line after it is a row of numbers. A column is named by the
// header's name or by its number, 1-based; the time column by default is `time` in a file with
// a header and column 1 in one without.
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace flexmoor::app {

struct MotionColumn {
  std::string name;  // the header's name, or
  int number = 0;    // 1-based; 0 with an empty name: the time column's default

  static MotionColumn named(std::string name) { return {std::move(name), 0}; }
  static MotionColumn numbered(int number) { return {"", number}; }
  bool byNumber() const { return number > 0; }
};

// What is wrong with the file, at its 1-based line (the last line read for the whole file).
struct MotionFileProblem {
  int line = 0;
  std::string what;
};

struct MotionSeries {
  std::vector<double> times, values;         // in the file's order, as written
  std::optional<MotionFileProblem> problem;  // set: the series is not usable
};

// The columns `time` and `value` of `in`.
MotionSeries readMotionColumns(std::istream& in, const MotionColumn& time,
                               const MotionColumn& value);

}  // namespace flexmoor::app
