#include "apps/case/read/motion_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace flexmoor::app {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> splitFields(const std::string& line, bool commas) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  std::string field;
  if (commas) {
    while (std::getline(ss, field, ',')) fields.push_back(trimmed(field));
  } else {
    while (ss >> field) fields.push_back(field);  // spaces and tabs
  }
  return fields;
}

std::optional<double> number(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(x)) return std::nullopt;
  return x;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

}  // namespace

MotionSeries readMotionColumns(std::istream& in, const MotionColumn& time,
                               const MotionColumn& value) {
  MotionSeries s;
  const auto fail = [&s](int line, const std::string& what) {
    s.problem = MotionFileProblem{line, what};
    s.times.clear();
    s.values.clear();
    return s;
  };
  std::string line;
  int number_of_line = 0;
  bool first = true, commas = false;
  int index[2] = {-1, -1};  // of the time and the value, 0-based
  std::string label[2];     // their names in messages: the header's, or the number
  const MotionColumn* columns[2] = {&time, &value};
  while (std::getline(in, line)) {
    ++number_of_line;
    const std::string text = trimmed(line);
    if (text.empty() || text[0] == '#') continue;
    if (first) {
      first = false;
      commas = text.find(',') != std::string::npos;
      const std::vector<std::string> names = splitFields(text, commas);
      bool header = false;
      for (const std::string& n : names) header = header || !number(n);
      for (int k = 0; k < 2; ++k) {
        const MotionColumn& c = *columns[k];
        if (c.byNumber()) {
          index[k] = c.number - 1;
          label[k] = std::to_string(c.number);
          if (header && index[k] >= static_cast<int>(names.size()))
            return fail(number_of_line, "no column " + std::to_string(c.number) +
                                            " (the header names " + std::to_string(names.size()) +
                                            ": " + joined(names) + ")");
          continue;
        }
        const std::string name = c.name.empty() ? std::string("time") : c.name;
        if (!header) {
          if (c.name.empty()) {  // the time column's default without a header: the first
            index[k] = 0;
            label[k] = "1";
            continue;
          }
          return fail(number_of_line,
                      "no line of column names to find '" + name +
                          "' in (the first line is numbers; name the column by its number, "
                          "1-based, like column: 2)");
        }
        label[k] = name;
        for (size_t j = 0; j < names.size() && index[k] < 0; ++j)
          if (names[j] == name) index[k] = static_cast<int>(j);
        if (index[k] < 0)
          return fail(number_of_line, "no column '" + name + "' (got " + joined(names) + ")");
      }
      if (header) continue;
    }
    const std::vector<std::string> fields = splitFields(text, commas);
    double row[2];
    for (int k = 0; k < 2; ++k) {
      if (index[k] >= static_cast<int>(fields.size()))
        return fail(number_of_line, "too few fields (got " + std::to_string(fields.size()) +
                                        ", expected column " + std::to_string(index[k] + 1) + ")");
      const auto x = number(fields[index[k]]);
      if (!x)
        return fail(number_of_line,
                    "not a number (got '" + fields[index[k]] + "' in column " + label[k] + ")");
      row[k] = *x;
    }
    s.times.push_back(row[0]);
    s.values.push_back(row[1]);
  }
  if (first)
    return fail(number_of_line,
                "no rows (expected lines of numbers: a time and the column's value)");
  return s;
}

}  // namespace flexmoor::app
