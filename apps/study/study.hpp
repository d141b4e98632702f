#pragma once
// A study as read from its YAML file (study_reader.hpp): a base case, the members that vary its
// values by their paths, and the series to collect from every member's run. README.md
// ("Studies") and `flexmoor study --help` describe the file.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

namespace flexmoor::app {

// A statistic of a collected series over its window (study_statistics.hpp).
enum class Statistic { Max, Min, Mean, Std, Amplitude, Mpm };

// The fit of the most probable maximum: Weibull of the peaks, Gumbel of the block maxima.
enum class MpmFit { Weibull, Gumbel };

struct MpmSpec {
  double duration = 0.0;  // s
  MpmFit fit = MpmFit::Weibull;
};

// One entry of collect: the quantity in a summary: entry's form (read against each member's case
// by readSeriesQuantity), its statistics and its spectrum.
struct CollectSpec {
  std::string name;  // the variable's name in series.nc and study.nc
  int line = 0;      // of the entry in the study file
  std::string path;  // "collect[1]"
  YAML::Node map;    // the entry, for the case reader
  std::vector<Statistic> statistics;
  std::optional<MpmSpec> mpm;
  std::optional<double> segment;  // Welch's segment, s; none: no spectrum
  std::string units;              // of the quantity in the members' cases ("ft", "lbf", "in")
};

// A value a member sets: the case value at `path` ("waves.spectrum.Hs") becomes `value`.
struct MemberValue {
  std::string path;
  YAML::Node value;
  int line = 0;  // of the value in the study file
};

struct StudyMember {
  int index = 0;                    // 1-based
  std::vector<MemberValue> values;  // list values first, then the grid's, in the file's order
  int line = 0;                     // its list item, else its first grid value
  std::string hash;                 // of the member's case text (member_case.hpp)
};

// A varied path as study.nc holds it (study_parameters.hpp).
struct StudyParameter {
  std::string path;                // as written: "waves.spectrum.Hs"
  std::string name;                // waves_spectrum_Hs
  bool numeric = true;             // every member's value a number: double, in the case's units
  std::string units;               // CF units of a numeric value ("1" for none), else ""
  std::vector<double> numbers;     // of each member, when numeric
  std::vector<std::string> texts;  // of each member, as written
};

struct Study {
  std::string file;  // the study file as given
  std::string title;
  std::string base_case;    // the base case's path (relative to the working directory)
  std::string case_name;    // the base case's name: the members' output files are <name>.*
  std::string unit_system;  // the base case's, "US (ft, slug, s, lbf)": the units of study.nc
  std::vector<StudyMember> members;
  std::vector<StudyParameter> parameters;
  std::vector<CollectSpec> collect;
};

}  // namespace flexmoor::app
