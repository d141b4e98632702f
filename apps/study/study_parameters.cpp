#include "apps/study/study_parameters.hpp"

#include <cstdlib>
#include <optional>

#include "apps/case/units.hpp"
#include "apps/study/value_path.hpp"

namespace flexmoor::app {
namespace {

struct Number {
  double si = 0.0;
  Dimension dimension;
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
    return Number{value * unit.si_factor, unit.dimension};
  } catch (const UnitError&) {
    return std::nullopt;
  }
}

std::string text(const YAML::Node& n) { return n.IsScalar() ? n.Scalar() : YAML::Dump(n); }

}  // namespace

std::string cfUnits(int mass, int length, int time) {
  if (mass == 1 && length == 1 && time == -2) return "N";
  if (mass == 1 && length == -1 && time == -2) return "Pa";
  std::string units;
  for (const auto& [name, exponent] :
       {std::pair<const char*, int>{"kg", mass}, {"m", length}, {"s", time}}) {
    if (exponent == 0) continue;
    units += (units.empty() ? "" : " ") + std::string(name) +
             (exponent == 1 ? "" : std::to_string(exponent));
  }
  return units.empty() ? "1" : units;
}

std::vector<StudyParameter> studyParameters(const std::vector<StudyMember>& members,
                                            const YAML::Node& base) {
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
    std::optional<Dimension> dimension;
    for (const StudyMember& m : members) {
      std::string value = base_value ? text(*base_value) : "";
      for (const MemberValue& v : m.values)
        if (v.path == p.path) value = text(v.value);
      p.texts.push_back(value);
      const auto n = number(value);
      if (!n || (dimension && *dimension != n->dimension)) {
        p.numeric = false;
        continue;
      }
      dimension = n->dimension;
      p.numbers.push_back(n->si);
    }
    if (!p.numeric) {
      p.numbers.clear();
    } else if (dimension && *dimension != Dimension{}) {
      p.units = cfUnits(dimension->mass, dimension->length, dimension->time);
    }
  }
  return parameters;
}

}  // namespace flexmoor::app
