#include "apps/case/read/read_motion.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>

#include "apps/case/input/units.hpp"
#include "apps/case/read/motion_file.hpp"
#include "apps/common/format_number.hpp"
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

// A column as `key` gives it: a whole number (1-based) or a name.
std::optional<MotionColumn> readColumn(Input& in, const YAML::Node& n, const std::string& path) {
  if (n.IsScalar() && !n.Scalar().empty() &&
      n.Scalar().find_first_not_of("+-0123456789") == std::string::npos) {
    const auto number = in.integer(n, path + " (a column number, 1-based)", 1);
    if (!number) return std::nullopt;
    return MotionColumn::numbered(*number);
  }
  const auto name = in.text(n, path);
  if (!name) return std::nullopt;
  return MotionColumn::named(*name);
}

// The columns `time` and `column` of `file` (errors at `at`, the file's line in the message).
std::optional<Samples> readColumns(Input& in, const YAML::Node& at, const std::string& path,
                                   const fs::path& file, const MotionColumn& time,
                                   const MotionColumn& column) {
  std::ifstream stream(file);
  if (!stream) {
    in.diag.error(at, path + ": cannot read " + file.string() +
                          " (expected a file of time series, relative to the case file)");
    return std::nullopt;
  }
  MotionSeries series = readMotionColumns(stream, time, column);
  if (series.problem) {
    in.diag.error(at, path + ": " + file.filename().string() + " line " +
                          std::to_string(series.problem->line) + ": " + series.problem->what);
    return std::nullopt;
  }
  return Samples{std::move(series.times), std::move(series.values)};
}

std::shared_ptr<const model::TimeFunction> readFile(Input& in, Fields& f, const QuantityKind& kind,
                                                    const std::string& case_file) {
  const YAML::Node* c = f.require("column");
  const auto name = in.text(*f.find("file"), f.path("file"));
  const auto column = c ? readColumn(in, *c, f.path("column")) : std::nullopt;
  std::optional<MotionColumn> time = MotionColumn{};  // `time`, or column 1 without a header
  if (const YAML::Node* t = f.find("time_column")) time = readColumn(in, *t, f.path("time_column"));
  const double offset = in.quantityOr(f, "time_offset", kind::kTime, Limit::Any, 0.0);
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
  auto samples = readColumns(in, *f.find("file"), f.path("file"), file, *time, *column);
  if (!samples) return nullptr;
  for (double& t : samples->times) t += offset;
  for (double& v : samples->values) v *= scale;
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
    Fields f(in.diag, n, path, {"file", "column", "time_column", "time_offset", "unit"});
    return readFile(in, f, kind, case_file);
  }
  Fields f(in.diag, n, path, {"amplitude", "period", "phase"});
  if (!f.isMap()) return nullptr;
  return readSine(in, f, kind);
}

}  // namespace flexmoor::app
