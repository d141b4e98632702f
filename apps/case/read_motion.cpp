#include "apps/case/read_motion.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "apps/case/units.hpp"
#include "libstruct/model/cubic_spline_function.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

struct Samples {
  std::vector<double> times, values;
};

// The samples' spline, or an error at `n` when the times do not increase strictly.
std::shared_ptr<const model::TimeFunction> spline(Input& in, const YAML::Node& n,
                                                  const std::string& path, Samples s) {
  if (s.times.empty()) {
    in.diag.error(n, path + ": no samples (expected at least one time and value)");
    return nullptr;
  }
  const auto wrong = std::adjacent_find(s.times.begin(), s.times.end(), std::greater_equal<>());
  if (wrong != s.times.end()) {
    in.diag.error(n, path + ": times not increasing (got " + formatNumber(*(wrong + 1)) +
                         " after " + formatNumber(*wrong) +
                         ", expected strictly increasing times)");
    return nullptr;
  }
  return std::make_shared<model::CubicSplineFunction>(std::move(s.times), std::move(s.values));
}

std::shared_ptr<const model::TimeFunction> readTable(Input& in, Fields& f,
                                                     const QuantityKind& kind) {
  const YAML::Node& table = *f.find("table");
  const std::string path = f.path("table");
  Samples s;
  bool ok = true;
  const std::vector<YAML::Node> rows = listItems(in.diag, table, path);
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::string row = itemPath(path, i);
    if (!rows[i].IsSequence() || rows[i].size() != 2) {
      in.diag.error(rows[i],
                    row + ": expected a pair [time, value] (got " + describeNode(rows[i]) + ")");
      ok = false;
      continue;
    }
    const auto t = in.quantity(rows[i][0], row + ".time", kind::kTime);
    const auto v = in.quantity(rows[i][1], row + ".value", kind);
    ok = ok && t && v;
    if (t && v) s.times.push_back(*t), s.values.push_back(*v);
  }
  if (!ok || !table.IsSequence()) return nullptr;
  return spline(in, table, path, std::move(s));
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) {
    const auto first = field.find_first_not_of(" \t\r");
    const auto last = field.find_last_not_of(" \t\r");
    fields.push_back(first == std::string::npos ? "" : field.substr(first, last - first + 1));
  }
  return fields;
}

// The columns `time` and `column` of a comma-separated file (errors at `at`, the file's line in
// the message).
std::optional<Samples> readColumns(Input& in, const YAML::Node& at, const std::string& path,
                                   const fs::path& file, const std::string& time,
                                   const std::string& column, double scale) {
  std::ifstream stream(file);
  if (!stream) {
    in.diag.error(at, path + ": cannot read " + file.string() +
                          " (expected a file of time series, relative to the case file)");
    return std::nullopt;
  }
  const auto fail = [&](int line, const std::string& what) {
    in.diag.error(
        at, path + ": " + file.filename().string() + " line " + std::to_string(line) + ": " + what);
    return std::nullopt;
  };
  Samples s;
  std::string line;
  int number = 0, time_index = -1, value_index = -1;
  bool header = true;
  while (std::getline(stream, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos ||
        line[line.find_first_not_of(" \t")] == '#')
      continue;
    const std::vector<std::string> fields = splitFields(line);
    if (header) {
      header = false;
      for (size_t k = 0; k < fields.size(); ++k) {
        if (fields[k] == time) time_index = static_cast<int>(k);
        if (fields[k] == column) value_index = static_cast<int>(k);
      }
      std::string names;
      for (const std::string& name : fields) names += (names.empty() ? "" : ", ") + name;
      if (time_index < 0) return fail(number, "no column '" + time + "' (got " + names + ")");
      if (value_index < 0) return fail(number, "no column '" + column + "' (got " + names + ")");
      continue;
    }
    double row[2];
    for (int k = 0; k < 2; ++k) {
      const int index = k == 0 ? time_index : value_index;
      if (index >= static_cast<int>(fields.size()))
        return fail(number, "too few fields (got " + std::to_string(fields.size()) +
                                ", expected column " + std::to_string(index + 1) + ")");
      const std::string& text = fields[index];
      char* end = nullptr;
      errno = 0;
      row[k] = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(row[k]))
        return fail(number,
                    "not a number (got '" + text + "' in column " + (k == 0 ? time : column) + ")");
    }
    s.times.push_back(row[0]);
    s.values.push_back(scale * row[1]);
  }
  if (header) return fail(number, "no header line (expected the column names)");
  return s;
}

std::shared_ptr<const model::TimeFunction> readFile(Input& in, Fields& f, const QuantityKind& kind,
                                                    const std::string& case_file) {
  const YAML::Node* c = f.require("column");
  const auto name = in.text(*f.find("file"), f.path("file"));
  const auto column = c ? in.text(*c, f.path("column")) : std::nullopt;
  std::optional<std::string> time = std::string("time");
  if (const YAML::Node* t = f.find("time_column")) time = in.text(*t, f.path("time_column"));
  double scale = 1.0;
  if (const YAML::Node* u = f.find("unit")) {  // the value of one of that unit
    const auto unit = in.text(*u, f.path("unit"));
    if (!unit) return nullptr;
    Diagnostics quiet(in.diag.file());
    Input parse(quiet, in.units);
    const auto one = parse.quantity(YAML::Node("1 " + *unit), f.path("unit"), kind);
    if (!one) {
      in.diag.error(*u, f.path("unit") + ": not a unit of " + std::string(kind.name) + " (got '" +
                            *unit + "')");
      return nullptr;
    }
    scale = *one;
  }
  if (!name || !column || !time) return nullptr;
  const fs::path file = fs::path(case_file).parent_path() / *name;
  auto samples = readColumns(in, *f.find("file"), f.path("file"), file, *time, *column, scale);
  if (!samples) return nullptr;
  return spline(in, *f.find("file"), f.path("file") + " (" + *name + ")", std::move(*samples));
}

}  // namespace

std::shared_ptr<const model::TimeFunction> readSine(Input& in, Fields& f,
                                                    const QuantityKind& amplitude_kind) {
  const YAML::Node* a = f.require("amplitude");
  const YAML::Node* p = f.require("period");
  const auto amplitude = a ? in.quantity(*a, f.path("amplitude"), amplitude_kind) : std::nullopt;
  const auto period =
      p ? in.quantity(*p, f.path("period"), kind::kTime, Limit::Positive) : std::nullopt;
  const double phase = in.quantityOr(f, "phase", kind::kNumber, Limit::Any, 0.0);
  const double offset = in.quantityOr(f, "offset", kind::kNumber, Limit::Any, 0.0);
  if (!amplitude || !period) return nullptr;
  return std::make_shared<model::SineFunction>(offset, *amplitude, *period, phase);
}

std::shared_ptr<const model::TimeFunction> readMotion(Input& in, const YAML::Node& n,
                                                      const std::string& path,
                                                      const QuantityKind& kind,
                                                      const std::string& case_file) {
  if (n.IsMap() && n["table"]) {
    Fields f(in.diag, n, path, {"table"});
    return readTable(in, f, kind);
  }
  if (n.IsMap() && n["file"]) {
    Fields f(in.diag, n, path, {"file", "column", "time_column", "unit"});
    return readFile(in, f, kind, case_file);
  }
  Fields f(in.diag, n, path, {"amplitude", "period", "phase"});
  if (!f.isMap()) return nullptr;
  return readSine(in, f, kind);
}

}  // namespace flexmoor::app
