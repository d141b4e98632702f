// The irregular forms of `waves:` (read_sea.hpp): every value checked with its line, so that
// build_ocean.cpp's synthesis and reconstruction cannot fail on a valid case.
#include "apps/case/read/read_sea.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "apps/case/read/read_fields.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

// DNV-RP-C205's limit of a sea state's average steepness S_p = 2 pi Hs / (g Tp^2): 1/15 for
// Tp <= 8 s, 1/25 for Tp >= 15 s, linear between (Tp in seconds, the time unit of both systems).
double steepnessLimit(double tp) {
  if (tp <= 8.0) return 1.0 / 15.0;
  if (tp >= 15.0) return 1.0 / 25.0;
  return 1.0 / 15.0 + (tp - 8.0) / 7.0 * (1.0 / 25.0 - 1.0 / 15.0);
}

// The `of: frequency` (f in Hz, S per Hz) or `circular_frequency` (omega in rad/s, S per rad/s)
// table of a spectrum: S >= 0, some S > 0.
std::optional<hydro::WaveSpectrum> readSpectrumTable(CaseBuilder& b, Fields& f) {
  const YAML::Node* of = f.require("of");
  const YAML::Node* t = f.require("table");
  const auto hertz = of ? b.in.choice<bool>(*of, f.path("of"),
                                            {{"frequency", true}, {"circular_frequency", false}})
                        : std::nullopt;
  if (!hertz || !t) return std::nullopt;
  const auto rows =
      readIncreasingRows(b, *t, f.path("table"), {*hertz ? "f" : "omega", kind::kFrequency},
                         {"S", kind::kSpectralDensity});
  if (!rows) return std::nullopt;
  bool positive = false;
  for (size_t i = 0; i < rows->size(); ++i) {
    const auto [w, S] = (*rows)[i];
    const std::string row = itemPath(f.path("table"), i);
    if (w < 0.0 || S < 0.0) {
      b.diag.error((*t)[i], row + ": negative (got [" + formatNumber(w) + ", " + formatNumber(S) +
                                "], expected a frequency >= 0 and a density >= 0)");
      return std::nullopt;
    }
    positive = positive || S > 0.0;
  }
  if (rows->size() < 2 || !positive) {
    b.diag.error(*t, f.path("table") + ": no sea in it (got " + std::to_string(rows->size()) +
                         " rows" + (positive ? "" : ", every S zero") +
                         ", expected 2 rows or more and some S > 0)");
    return std::nullopt;
  }
  const hydro::WaveSpectrum spectrum =
      *hertz ? hydro::WaveSpectrum::tablePerHertz(*rows) : hydro::WaveSpectrum::table(*rows);
  if (!(spectrum.peakFrequency() > 0.0)) {
    b.diag.error(*t, f.path("table") + ": the largest S is at zero frequency (got S(0) = " +
                         formatNumber(rows->front().second) +
                         ", expected a peak at a frequency > 0: the band is in ratios of it)");
    return std::nullopt;
  }
  return spectrum;
}

// spectrum: {type: jonswap, Hs, Tp, [gamma: 3.3]} | {type: pierson_moskowitz, Hs, Tp} |
// {type: table, of, table}; a sea state steeper than DNV's limit is refused.
std::optional<hydro::WaveSpectrum> readSpectrum(CaseBuilder& b, const YAML::Node& n,
                                                const std::string& path, double g) {
  const std::string type = peekText(n, "type");
  Fields f(b.diag, n, path,
           type == "table"               ? std::vector<std::string>{"type", "of", "table"}
           : type == "pierson_moskowitz" ? std::vector<std::string>{"type", "Hs", "Tp"}
                                         : std::vector<std::string>{"type", "Hs", "Tp", "gamma"});
  const YAML::Node* t = f.require("type");
  if (!t) return std::nullopt;
  enum Type { Jonswap, PiersonMoskowitz, Table };
  const auto kind = b.in.choice<Type>(
      *t, f.path("type"),
      {{"jonswap", Jonswap}, {"pierson_moskowitz", PiersonMoskowitz}, {"table", Table}});
  if (!kind) return std::nullopt;
  if (*kind == Table) return readSpectrumTable(b, f);
  const auto hs = requiredQuantity(b, f, "Hs", kind::kLength, Limit::Positive);
  const auto tp = requiredQuantity(b, f, "Tp", kind::kTime, Limit::Positive);
  auto gamma = *kind == Jonswap
                   ? optionalQuantity(b, f, "gamma", kind::kNumber, Limit::Positive, 3.3)
                   : std::optional<double>(1.0);
  if (gamma && *gamma < 1.0) {
    b.diag.error(*f.find("gamma"), f.path("gamma") + ": below 1 (got " + formatNumber(*gamma) +
                                       ", expected gamma >= 1: 1 is Pierson-Moskowitz, 3.3 the "
                                       "mean JONSWAP peak)");
    gamma.reset();
  }
  if (!hs || !tp || !gamma) return std::nullopt;
  const double steepness = 2.0 * kPi * *hs / (g * *tp * *tp), limit = steepnessLimit(*tp);
  if (steepness > limit) {
    b.diag.error(*f.find("Hs"),
                 f.path("Hs") +
                     ": the sea state is too steep to exist (got 2 pi "
                     "Hs / (g Tp^2) = " +
                     formatNumber(steepness) + ", expected at most " + formatNumber(limit) +
                     ", DNV-RP-C205's limit of the average steepness at Tp = " + formatNumber(*tp) +
                     " s)");
    return std::nullopt;
  }
  return hydro::WaveSpectrum::jonswap(*hs, *tp, *gamma);
}

// band: [lo, hi], ratios of the peak frequency, 0 <= lo < hi.
std::optional<std::pair<double, double>> readBand(CaseBuilder& b, const YAML::Node& n,
                                                  const std::string& path) {
  if (!n.IsSequence() || n.size() != 2) {
    b.diag.error(n, path + ": expected [low, high], two ratios of the peak frequency (got " +
                        describeNode(n) + ")");
    return std::nullopt;
  }
  const auto lo = b.in.quantity(n[0], path + ".low", kind::kNumber, Limit::NonNegative);
  const auto hi = b.in.quantity(n[1], path + ".high", kind::kNumber, Limit::Positive);
  if (!lo || !hi) return std::nullopt;
  if (!(*hi > *lo)) {
    b.diag.error(n, path + ": empty (got [" + formatNumber(*lo) + ", " + formatNumber(*hi) +
                        "], expected low < high)");
    return std::nullopt;
  }
  return std::pair{*lo, *hi};
}

// spreading: {s, directions}.
bool readSpreading(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                   hydro::SynthesisOptions& o) {
  Fields f(b.diag, n, path, {"s", "directions"});
  const auto s = requiredQuantity(b, f, "s", kind::kNumber, Limit::Positive);
  const YAML::Node* d = f.require("directions");
  const auto directions = d ? b.in.integer(*d, f.path("directions"), 1, 360) : std::nullopt;
  if (!s || !directions) return false;
  o.spreading_s = *s;
  o.directions = *directions;
  return true;
}

std::string discretisationName(
    const std::vector<std::pair<std::string, hydro::Discretisation>>& names,
    hydro::Discretisation d) {
  for (const auto& [name, value] : names)
    if (value == d) return name;
  return "";
}

// The harmonics m of d omega = 2 pi / T inside [lo, hi] (as wave_synthesis.cpp takes them).
long gridCount(double period, double lo, double hi) {
  const double dw = 2.0 * kPi / period;
  return static_cast<long>(std::floor(hi / dw)) -
         std::max(1L, static_cast<long>(std::ceil(lo / dw))) + 1;
}

// `file:` of a measured record: lines "t, eta" (commas, semicolons or blanks between), '#'
// comments and blank lines skipped, a first line that is not two numbers taken as a header;
// plain numbers in the case's units. nullopt when unreadable (reported at the key).
std::optional<std::vector<std::pair<double, double>>> readRecordFile(CaseBuilder& b,
                                                                     const YAML::Node& n,
                                                                     const std::string& path) {
  const auto name = b.in.text(n, path);
  if (!name) return std::nullopt;
  namespace fs = std::filesystem;
  fs::path file(*name);
  if (file.is_relative()) file = fs::path(b.c.file).parent_path() / file;
  std::ifstream in(file);
  if (!in) {
    b.diag.error(n, path + ": cannot read the record (got '" + *name +
                        "', expected a CSV file of t, "
                        "eta, relative to the case file's folder: " +
                        file.string() + ")");
    return std::nullopt;
  }
  std::vector<std::pair<double, double>> rows;
  std::string line;
  bool first = true;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (char& ch : line)
      if (ch == ',' || ch == ';' || ch == '\t' || ch == '\r') ch = ' ';
    std::istringstream fields(line);
    double t, eta;
    std::string rest;
    if (!(fields >> std::ws) || fields.eof()) continue;  // blank
    const bool two = static_cast<bool>(fields >> t >> eta) && !(fields >> rest);
    if (!two && first) {
      first = false;  // a header
      continue;
    }
    first = false;
    if (!two || !std::isfinite(t) || !std::isfinite(eta)) {
      b.diag.error(n, path + ": '" + *name + "' line " + std::to_string(number) +
                          " is not a sample (got '" + line + "', expected two numbers t, eta)");
      return std::nullopt;
    }
    if (!rows.empty() && !(t > rows.back().first)) {
      b.diag.error(n, path + ": '" + *name + "' line " + std::to_string(number) +
                          ": t not increasing (got " + formatNumber(t) + " after " +
                          formatNumber(rows.back().first) + ", expected t increasing strictly)");
      return std::nullopt;
    }
    rows.emplace_back(t, eta);
  }
  return rows;
}

// The record from its rows: 4 samples or more, evenly spaced (the FFT's grid): every t_i within
// 1e-6 dt of t_0 + i dt, dt = (t_last - t_0) / (n - 1).
std::optional<hydro::ElevationRecord> evenRecord(
    CaseBuilder& b, const YAML::Node& at, const std::string& path,
    const std::vector<std::pair<double, double>>& rows) {
  if (rows.size() < 4) {
    b.diag.error(at, path + ": too short a record (got " + std::to_string(rows.size()) +
                         " samples, expected 4 or more)");
    return std::nullopt;
  }
  hydro::ElevationRecord r;
  r.start = rows.front().first;
  r.dt = (rows.back().first - r.start) / (rows.size() - 1);
  for (size_t i = 0; i < rows.size(); ++i) {
    const double expected = r.start + i * r.dt;
    if (std::abs(rows[i].first - expected) > 1e-6 * r.dt) {
      b.diag.error(at, path + ": not evenly sampled at sample " + std::to_string(i + 1) +
                           " (got t = " + formatNumber(rows[i].first) + ", expected t0 + i dt = " +
                           formatNumber(expected) + " with dt = " + formatNumber(r.dt) +
                           ": the FFT needs one sampling interval)");
      return std::nullopt;
    }
    r.elevation.push_back(rows[i].second);
  }
  return r;
}

}  // namespace

const std::vector<std::string>& spectralSeaKeys() {
  static const std::vector<std::string> keys = {"spectrum",      "components", "discretisation",
                                                "repeat_period", "seed",       "heading",
                                                "spreading",     "band"};
  return keys;
}

void readSpectralSea(CaseBuilder& b, Fields& f, OceanSpec& h) {
  SpectralSeaSpec spec;
  spec.line = f.keyLine("spectrum");
  hydro::SynthesisOptions& o = spec.options;
  const auto spectrum = readSpectrum(b, *f.find("spectrum"), f.path("spectrum"), h.water.gravity);
  bool ok = spectrum.has_value();
  const std::vector<std::pair<std::string, hydro::Discretisation>> discretisations = {
      {"equal", hydro::Discretisation::Equal},
      {"random_bins", hydro::Discretisation::RandomBins},
      {"equal_energy", hydro::Discretisation::EqualEnergy}};
  if (const YAML::Node* d = f.find("discretisation")) {
    const auto choice =
        b.in.choice<hydro::Discretisation>(*d, f.path("discretisation"), discretisations);
    ok = ok && choice;
    o.discretisation = choice.value_or(o.discretisation);
  }
  const YAML::Node* components = f.find("components");
  const YAML::Node* period = f.find("repeat_period");
  if (components) {
    const auto n = b.in.integer(*components, f.path("components"), 1, 100000);
    ok = ok && n;
    o.components = n.value_or(o.components);
  }
  if (period) {
    if (o.discretisation != hydro::Discretisation::Equal || components) {
      b.diag.error(*period,
                   f.path("repeat_period") +
                       (components ? ": give either components or repeat_period, not both"
                                   : ": only for an FFT grid (got discretisation: " +
                                         discretisationName(discretisations, o.discretisation) +
                                         ", expected discretisation: equal, which repeats)"));
      ok = false;
    } else {
      const auto t = b.in.quantity(*period, f.path("repeat_period"), kind::kTime, Limit::Positive);
      ok = ok && t;
      o.repeat_period = t.value_or(0.0);
    }
  }
  if (const YAML::Node* s = f.find("seed")) {
    const auto seed = b.in.integer(*s, f.path("seed"), 0);
    ok = ok && seed;
    o.seed = static_cast<uint64_t>(seed.value_or(0));
  }
  const auto heading = optionalQuantity(b, f, "heading", kind::kNumber, Limit::Any, 0.0);
  ok = ok && heading;
  o.heading = heading.value_or(0.0);
  if (const YAML::Node* s = f.find("spreading"))
    ok = readSpreading(b, *s, f.path("spreading"), o) && ok;
  std::optional<std::pair<double, double>> band;
  if (const YAML::Node* n = f.find("band")) {
    band = readBand(b, *n, f.path("band"));
    ok = ok && band;
  }
  if (!ok) return;
  // A table's band is where it is given, unless the case narrows it.
  const double wp = spectrum->peakFrequency();
  if (!band && std::isfinite(spectrum->support().second))
    band = std::pair{spectrum->support().first / wp, spectrum->support().second / wp};
  if (band) std::tie(o.omega_min_ratio, o.omega_max_ratio) = *band;
  const long grid = o.repeat_period > 0.0
                        ? gridCount(o.repeat_period, o.omega_min_ratio * wp, o.omega_max_ratio * wp)
                        : 1;
  if (grid < 1 || grid > 100000) {
    const double width = (o.omega_max_ratio - o.omega_min_ratio) * wp;
    b.diag.error(*period, f.path("repeat_period") +
                              (grid < 1 ? ": no frequency of the grid in the band (got "
                                        : ": too many components (got ") +
                              formatNumber(o.repeat_period) + " s, " + std::to_string(grid) +
                              " frequencies, expected 1 to 100000: T between 2 pi / " +
                              formatNumber(width) +
                              " rad/s (the band's width) and 100000 times "
                              "that)");
    return;
  }
  spec.spectrum = *spectrum;
  h.spectral = spec;
}

void readMeasuredSea(CaseBuilder& b, const YAML::Node& n, const std::string& path, OceanSpec& h) {
  Fields f(b.diag, n, path, {"table", "file", "heading", "at", "cutoff"});
  const YAML::Node* table = f.find("table");
  const YAML::Node* file = f.find("file");
  if (!table == !file) {
    b.diag.error(n, path + ": give the record as table: [[t, eta], ...] or as file: CSV (got " +
                        (table ? "both" : "neither") + ")");
    return;
  }
  const auto rows = table ? readIncreasingRows(b, *table, f.path("table"), {"t", kind::kTime},
                                               {"eta", kind::kLength})
                          : readRecordFile(b, *file, f.path("file"));
  const auto heading = optionalQuantity(b, f, "heading", kind::kNumber, Limit::Any, 0.0);
  const auto cutoff = optionalQuantity(b, f, "cutoff", kind::kFrequency, Limit::Positive,
                                       std::numeric_limits<double>::infinity());
  Eigen::Vector2d gauge = Eigen::Vector2d::Zero();
  bool gauge_ok = true;
  if (const YAML::Node* at = f.find("at")) {
    const auto x = at->IsSequence() && at->size() == 2
                       ? b.in.quantity((*at)[0], f.path("at") + ".x", kind::kLength)
                       : std::nullopt;
    const auto y = x ? b.in.quantity((*at)[1], f.path("at") + ".y", kind::kLength) : std::nullopt;
    if (!at->IsSequence() || at->size() != 2)
      b.diag.error(*at, f.path("at") +
                            ": expected [x, y], the gauge's position, two lengths (got " +
                            describeNode(*at) + ")");
    gauge_ok = x && y;
    if (gauge_ok) gauge = Eigen::Vector2d(*x, *y);
  }
  if (!rows || !heading || !cutoff || !gauge_ok) return;
  const auto record =
      evenRecord(b, table ? *table : *file, table ? f.path("table") : f.path("file"), *rows);
  if (!record) return;
  double mean = 0.0, largest = 0.0;
  for (double e : record->elevation) {
    mean += e / record->elevation.size();
    largest = std::max(largest, std::abs(e));
  }
  if (std::abs(mean) > 1e-6 * largest)
    b.diag.warning(f.keyLine(table ? "table" : "file"),
                   path + ": the record's mean " + formatNumber(mean) + " " +
                       unitNames(b.c.units).length +
                       " is a still-water offset, not a wave: the sea is the record less it");
  h.measured = MeasuredSeaSpec{*record, *heading, gauge, 2.0 * kPi * *cutoff, lineOf(n)};
}

std::optional<hydro::TimeRamp> readRamp(CaseBuilder& b, const YAML::Node& n,
                                        const std::string& path) {
  Fields f(b.diag, n, path, {"duration", "start"});
  const auto duration = requiredQuantity(b, f, "duration", kind::kTime, Limit::Positive);
  const auto start = optionalQuantity(b, f, "start", kind::kTime, Limit::Any, 0.0);
  if (!duration || !start) return std::nullopt;
  return hydro::TimeRamp{*start, *duration};
}

}  // namespace flexmoor::app
