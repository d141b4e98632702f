#pragma once
// The varied paths of a study as study.nc holds them: one value per member (the member's own, or
// the base case's when the member leaves the path alone). A parameter whose every value is a
// number, or a "NUMBER UNIT" of one dimension, is numeric, in SI with CF units ("2 ft" is
// 0.6096 m); any other is text, as written.
#include <string>
#include <vector>

#include "apps/study/study.hpp"

namespace flexmoor::app {

// The parameters of study.members, in the order their paths first appear; `base` is the base
// case's document (every path is in it).
std::vector<StudyParameter> studyParameters(const std::vector<StudyMember>& members,
                                            const YAML::Node& base);

// CF units of a dimension in SI: "m", "s", "N", "Pa", "kg m-3"; "1" for none.
std::string cfUnits(int mass, int length, int time);

}  // namespace flexmoor::app
