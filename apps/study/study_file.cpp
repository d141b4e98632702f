#include "apps/study/study_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>

#include "apps/common/format_number.hpp"
#include "apps/output/atomic_output.hpp"
#include "apps/output/netcdf_file.hpp"
#include "apps/study/member_store.hpp"
#include "apps/study/series_file.hpp"
#include "apps/study/study_statistics.hpp"
#include "libhydro/signal/extremes.hpp"
#include "libhydro/signal/welch.hpp"

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

struct StatisticInfo {
  Statistic statistic;
  const char* suffix;
  const char* long_name;
};

const std::vector<StatisticInfo>& writtenStatistics() {
  static const std::vector<StatisticInfo> infos = {
      {Statistic::Max, "max", "maximum"},
      {Statistic::Min, "min", "minimum"},
      {Statistic::Mean, "mean", "mean"},
      {Statistic::Std, "std", "standard deviation"},
      {Statistic::Amplitude, "amplitude", "amplitude (max - min) / 2"},
      {Statistic::Mpm, "mpm", "most probable maximum"}};
  return infos;
}

double statisticValue(const SeriesStatistics& s, Statistic which) {
  switch (which) {
    case Statistic::Max:
      return s.max;
    case Statistic::Min:
      return s.min;
    case Statistic::Mean:
      return s.mean;
    case Statistic::Std:
      return s.std;
    case Statistic::Amplitude:
      return s.amplitude;
    case Statistic::Mpm:
      break;  // mostProbableMaximum: of the record, not of its statistics
  }
  return NC_FILL_DOUBLE;
}

// The most probable maximum over the spec's duration (libhydro/signal/extremes.hpp) of the
// series resampled at its median time step; the fill value when the record is too short for
// the fit (fewer than 30 peaks above the mean, or 10 blocks of 20 zero-crossing periods).
double mostProbableMaximum(const std::vector<double>& t, const std::vector<double>& v,
                           const MpmSpec& mpm) {
  const double dt = medianStep(t, v);
  if (!(dt > 0.0)) return NC_FILL_DOUBLE;
  const signal::ExtremeFit fit =
      mpm.fit == MpmFit::Weibull ? signal::ExtremeFit::Weibull : signal::ExtremeFit::Gumbel;
  try {
    return signal::mostProbableMaximum(resampled(t, v, dt), dt, mpm.duration, fit);
  } catch (const std::invalid_argument&) {
    return NC_FILL_DOUBLE;
  }
}

std::string windowText(const SeriesData::Variable& v, const std::string& time_unit) {
  const bool from = std::isfinite(v.from), to = std::isfinite(v.to);
  const auto num = [](double x) { return formatNumber(x); };
  if (from && to)
    return " over " + num(v.from) + " " + time_unit + " <= t <= " + num(v.to) + " " + time_unit;
  if (from) return " over t >= " + num(v.from) + " " + time_unit;
  if (to) return " over t <= " + num(v.to) + " " + time_unit;
  return " over the step";
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
  return text;
}

// A density per circular frequency of a quantity in `units`: "N2 s rad-1", "(m/s)2 s rad-1".
std::string psdUnits(const std::string& units) {
  if (units.empty()) return "";
  const bool word = std::all_of(units.begin(), units.end(), [](char ch) {
    return std::isalpha(static_cast<unsigned char>(ch));
  });
  return (word ? units : "(" + units + ")") + "2 s rad-1";
}

// The spectra's one axis: L samples of dt a segment.
struct SpectrumAxis {
  int samples = 0;
  double dt = 0.0;
};

}  // namespace

int writeStudyFile(const Study& study, const std::string& dir) {
  const size_t n = study.members.size();
  std::vector<std::string> names;
  for (const CollectSpec& c : study.collect) names.push_back(c.name);
  std::vector<MemberOutcome> outcomes;
  std::vector<std::optional<SeriesData>> series(n);
  for (size_t i = 0; i < n; ++i) {
    outcomes.push_back(readOutcome(dir, study.members[i]));
    if (outcomes[i].status != kComplete) continue;
    try {
      series[i] = readSeriesFile(seriesPath(dir, study.members[i].index), names);
    } catch (const std::exception& e) {
      outcomes[i] = {kFailed, e.what()};
    }
  }
  // The spectra's axis.
  std::optional<double> segment;
  for (const CollectSpec& c : study.collect)
    if (c.segment) segment = c.segment;
  SpectrumAxis axis;
  if (segment) {
    double largest = 0.0;
    for (const auto& s : series)
      if (s)
        for (const SeriesData::Variable& v : s->variables)
          largest = std::max(largest, medianStep(s->time, v.values));
    if (largest > 0.0) {
      axis.samples =
          std::max(4, 2 * static_cast<int>(std::ceil(*segment / (2.0 * largest) - 1e-9)));
      axis.dt = *segment / axis.samples;
    }
  }
  const std::string partial = (fs::path(dir) / "study.nc.partial").string();
  int complete = 0;
  {
    NetcdfFile file(partial);
    file.putAttribute(NC_GLOBAL, "Conventions", std::string("CF-1.8"));
    file.putAttribute(NC_GLOBAL, "title", study.title);
    file.putAttribute(NC_GLOBAL, "study_file", study.file);
    file.putAttribute(NC_GLOBAL, "base_case", study.base_case);
    // The base case's units: the parameters' and, unless a collect: entry gives unit:, the
    // statistics' (each variable states its own).
    file.putAttribute(NC_GLOBAL, "unit_system", study.unit_system);
    std::vector<std::string> parameter_names;
    for (const StudyParameter& p : study.parameters) parameter_names.push_back(p.name);
    file.putAttribute(NC_GLOBAL, "study_parameters", joined(parameter_names));
    // CF's auxiliary coordinates: xarray makes the parameters coordinates of every variable.
    const std::string coordinates = joined(parameter_names);
    file.putAttribute(NC_GLOBAL, "collect", joined(names));
    file.putAttribute(NC_GLOBAL, "flexmoor_version", std::string(FLEXMOOR_VERSION));
    const int member_dim = file.defineDimension("member", n);
    const int member = file.defineVariable("member", NC_INT, {member_dim}, "study member");
    std::vector<int> parameter_ids;
    for (const StudyParameter& p : study.parameters) {
      int id;
      if (p.numeric) {
        id = file.defineVariable(p.name, NC_DOUBLE, {member_dim}, p.path, p.units);
      } else {
        size_t length = 1;
        for (const std::string& t : p.texts) length = std::max(length, t.size());
        const int strlen = file.defineDimension(p.name + "_strlen", length);
        id = file.defineVariable(p.name, NC_CHAR, {member_dim, strlen}, p.path);
      }
      file.putAttribute(id, "flexmoor_path", p.path);
      parameter_ids.push_back(id);
    }
    const int status = file.defineVariable("status", NC_INT, {member_dim}, "member status");
    file.putAttribute(status, "flag_values", std::vector<int>{0, 2, 3, 4});
    if (!coordinates.empty()) file.putAttribute(status, "coordinates", coordinates);
    file.putAttribute(status, "flag_meanings",
                      std::string("complete bad_input not_converged failed"));
    size_t error_length = 1;
    for (const MemberOutcome& o : outcomes) error_length = std::max(error_length, o.error.size());
    const int error_dim = file.defineDimension("error_strlen", error_length);
    const int error = file.defineVariable("error", NC_CHAR, {member_dim, error_dim},
                                          "why the member failed (empty when complete)");
    // The statistics' and spectra's variables, in the order of collect: and of the statistics.
    struct Output {
      size_t collect;
      std::optional<Statistic> statistic;  // none: the spectrum
      int id;
    };
    std::vector<Output> outputs;
    int frequency_dim = -1, frequency = -1;
    if (axis.samples > 0) {
      frequency_dim = file.defineDimension("frequency", axis.samples / 2 + 1);
      frequency = file.defineVariable("frequency", NC_DOUBLE, {frequency_dim}, "circular frequency",
                                      "rad s-1");
      file.putAttribute(frequency, "standard_name", std::string("angular_frequency"));
    }
    const SeriesData::Variable* example = nullptr;
    for (size_t k = 0; k < study.collect.size(); ++k) {
      const CollectSpec& c = study.collect[k];
      example = nullptr;
      for (const auto& s : series)
        if (s && !example) example = &s->variables[k];
      const std::string units = example && !example->units.empty() ? example->units : c.units;
      const std::string window = example ? windowText(*example, "s") : "";
      for (const StatisticInfo& info : writtenStatistics()) {
        if (std::find(c.statistics.begin(), c.statistics.end(), info.statistic) ==
            c.statistics.end())
          continue;
        const int id =
            file.defineVariable(c.name + "_" + info.suffix, NC_DOUBLE, {member_dim},
                                std::string(info.long_name) + " of " + c.name + window, units);
        file.putAttribute(id, "_FillValue", NC_FILL_DOUBLE);
        if (!coordinates.empty()) file.putAttribute(id, "coordinates", coordinates);
        if (info.statistic == Statistic::Mpm && c.mpm) {
          file.putAttribute(id, "mpm_duration", c.mpm->duration);
          file.putAttribute(id, "mpm_fit",
                            std::string(c.mpm->fit == MpmFit::Weibull ? "weibull" : "gumbel"));
        }
        outputs.push_back({k, info.statistic, id});
      }
      if (c.segment && frequency_dim >= 0) {
        const int id = file.defineVariable(c.name + "_psd", NC_DOUBLE, {member_dim, frequency_dim},
                                           "power spectral density of " + c.name + window +
                                               " (Welch, Hann, half overlap, segment " +
                                               formatNumber(*c.segment) + " s)",
                                           psdUnits(units));
        file.putAttribute(id, "_FillValue", NC_FILL_DOUBLE);
        if (!coordinates.empty()) file.putAttribute(id, "coordinates", coordinates);
        outputs.push_back({k, std::nullopt, id});
      }
    }
    file.endDefine();
    std::vector<int> indices, statuses;
    for (size_t i = 0; i < n; ++i) {
      indices.push_back(study.members[i].index);
      statuses.push_back(outcomes[i].status);
      complete += outcomes[i].status == kComplete;
    }
    file.put(member, {0}, {n}, indices.data());
    file.put(status, {0}, {n}, statuses.data());
    for (size_t p = 0; p < study.parameters.size(); ++p) {
      const StudyParameter& sp = study.parameters[p];
      if (sp.numeric) {
        file.put(parameter_ids[p], {0}, {n}, sp.numbers.data());
        continue;
      }
      size_t length = 1;
      for (const std::string& t : sp.texts) length = std::max(length, t.size());
      std::string block(n * length, '\0');
      for (size_t i = 0; i < n; ++i) sp.texts[i].copy(&block[i * length], length);
      file.put(parameter_ids[p], {0, 0}, {n, length}, block.data());
    }
    std::string errors(n * error_length, '\0');
    for (size_t i = 0; i < n; ++i) outcomes[i].error.copy(&errors[i * error_length], error_length);
    file.put(error, {0, 0}, {n, error_length}, errors.data());
    if (frequency >= 0) {
      std::vector<double> omega(axis.samples / 2 + 1);
      const double pi = std::acos(-1.0);
      for (size_t k = 0; k < omega.size(); ++k)
        omega[k] = 2.0 * pi * static_cast<double>(k) / (axis.samples * axis.dt);
      file.put(frequency, {0}, {omega.size()}, omega.data());
    }
    for (const Output& o : outputs) {
      if (o.statistic) {
        std::vector<double> values(n, NC_FILL_DOUBLE);
        for (size_t i = 0; i < n; ++i) {
          if (!series[i]) continue;
          const SeriesData::Variable& v = series[i]->variables[o.collect];
          const CollectSpec& c = study.collect[o.collect];
          if (*o.statistic == Statistic::Mpm) {
            if (c.mpm) values[i] = mostProbableMaximum(series[i]->time, v.values, *c.mpm);
            continue;
          }
          try {
            values[i] = statisticValue(seriesStatistics(series[i]->time, v.values), *o.statistic);
          } catch (const std::logic_error&) {  // no window in this member's record: left filled
          }
        }
        file.put(o.id, {0}, {n}, values.data());
        continue;
      }
      const size_t bins = axis.samples / 2 + 1;
      std::vector<double> psd(n * bins, NC_FILL_DOUBLE);
      for (size_t i = 0; i < n; ++i) {
        if (!series[i]) continue;
        const SeriesData::Variable& v = series[i]->variables[o.collect];
        const std::vector<double> record = resampled(series[i]->time, v.values, axis.dt);
        if (static_cast<int>(record.size()) < axis.samples) continue;  // shorter than a segment
        const signal::SpectralEstimate estimate = signal::welch(record, axis.dt, axis.samples);
        std::copy(estimate.density.begin(), estimate.density.end(), psd.begin() + i * bins);
      }
      file.put(o.id, {0, 0}, {n, bins}, psd.data());
    }
  }
  moveIntoPlace(partial, (fs::path(dir) / "study.nc").string());
  return complete;
}

}  // namespace flexmoor::app
