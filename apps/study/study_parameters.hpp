#pragma once
// The varied paths of a study as study.nc holds them: one value per member (the member's own, or
// the base case's when the member leaves the path alone). A parameter whose every value is a
// number, or a "NUMBER UNIT" of one dimension, is numeric, in the base case's unit system, the
// one its results and so the study's statistics are in ("2 ft" is 2 ft in a US case and 0.6096 m
// in an SI one), with CF units of that system: the dimension of a unit given, else the one the
// case reads the value as (QuantityMarks), else "1" (a count, a seed); any other is text, as
// written.
#include <string>
#include <vector>

#include "apps/case/input/yaml_input.hpp"
#include "apps/study/study.hpp"

namespace flexmoor::app {

// The parameters of study.members, in the order their paths first appear; `base` is the base
// case's document (every path is in it), `marks` what reading a member's case recorded of its
// values, `units` the base case's system.
std::vector<StudyParameter> studyParameters(const std::vector<StudyMember>& members,
                                            const YAML::Node& base, const QuantityMarks& marks,
                                            UnitSystem units);

}  // namespace flexmoor::app
