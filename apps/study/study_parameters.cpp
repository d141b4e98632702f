#include "apps/study/study_parameters.hpp"

#include <cstdlib>
#include <optional>

#include "apps/case/input/units.hpp"
#include "apps/study/value_path.hpp"

namespace flexmoor::app {
namespace {

// A value as written: with a unit, in SI of its dimension; without, the number as it is (in the
// case's units).
struct Number {
  double si = 0.0;
  Dimension dimension;
  bool with_unit = false;
};

// "2", "2 m", "3 h"; nullopt for anything else.
std::optional<Number> number(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin) return std::nullopt;
  std::string rest(end);
  const size_t first = rest.find_first_not_of(' ');
  if (first == std::string::npos) return Number{value, {}};
  if (first == 0) return std::nullopt;  // "2m" is not a number with a unit
  try {
    const Unit unit = parseUnit(rest.substr(first));
    return Number{value * unit.si_factor, unit.dimension, true};
  } catch (const UnitError&) {
    return std::nullopt;
  }
}

std::string text(const YAML::Node& n) { return n.IsScalar() ? n.Scalar() : YAML::Dump(n); }

}  // namespace

std::vector<StudyParameter> studyParameters(const std::vector<StudyMember>& members,
                                            const YAML::Node& base, const QuantityMarks& marks,
                                            UnitSystem units) {
  std::vector<StudyParameter> parameters;
  for (const StudyMember& m : members)
    for (const MemberValue& v : m.values) {
      bool known = false;
      for (const StudyParameter& p : parameters) known = known || p.path == v.path;
      if (!known) parameters.push_back({v.path, pathVariableName(v.path), true, "", {}, {}});
    }
  for (StudyParameter& p : parameters) {
    std::string missing;
    const auto base_value = nodeAtPath(base, p.path, missing);
    // The dimension the case reads the value as (a plain number is in the case's units).
    Dimension read;  // (GCC takes an optional's payload here for uninitialised)
    bool is_read = false;
    if (base_value)
      if (const std::optional<Dimension> d = marks.at(*base_value)) {
        read = *d;
        is_read = true;
      }
    std::optional<Dimension> dimension;
    std::vector<std::optional<Number>> numbers;
    for (const StudyMember& m : members) {
      std::string value = base_value ? text(*base_value) : "";
      for (const MemberValue& v : m.values)
        if (v.path == p.path) value = text(v.value);
      p.texts.push_back(value);
      numbers.push_back(number(value));
      const auto& n = numbers.back();
      if (!n) {
        p.numeric = false;
        continue;
      }
      if (!n->with_unit) continue;
      if (dimension && *dimension != n->dimension) p.numeric = false;
      dimension = n->dimension;
    }
    if (!p.numeric) continue;
    if (!dimension) dimension = is_read ? read : Dimension{};
    if (is_read && read != *dimension) {  // a unit of another dimension than the case reads
      p.numeric = false;
      continue;
    }
    const double scale = systemScale(*dimension, units);
    for (const auto& n : numbers) p.numbers.push_back(n->with_unit ? n->si / scale : n->si);
    p.units = systemUnits(*dimension, units);
  }
  return parameters;
}

}  // namespace flexmoor::app
