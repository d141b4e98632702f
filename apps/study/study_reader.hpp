#pragma once
// Reads a study file into a validated Study, and builds and checks every member's case before
// anything runs. Every problem is reported at once as `FILE:LINE: what is wrong (got X, expected
// Y)` in one CaseError.
//
// Schema (README.md "Studies"):
//   title:   [one line]
//   case:    the base case, relative to the study file
//   grid:    [PATH: [VALUE, ...], ...]   every combination, the last path varying fastest
//   list:    [- {PATH: VALUE, ...}]      members; each crossed with the grid when both are given
//   collect: - {name, quantity, ... as a summary: entry (node, element, end, scale, unit, step,
//               window), [statistics: [max, min, mean, std, amplitude, mpm]; default all but mpm],
//               [mpm: {duration, fit: weibull | gumbel}] (with mpm only),
//               [spectrum: {segment}]}
// PATH: a value of the base case by its keys joined with '.', a list's index 0-based
// ("waves.spectrum.Hs", "waves.components.0.period"); it must be in the base case.
#include <string>

#include "apps/study/study.hpp"

namespace flexmoor::app {

// Reads and validates the study and every member's case; throws CaseError.
Study readStudy(const std::string& path);

// Whether the YAML file is a study (its top-level map has both case: and collect:).
bool isStudyFile(const std::string& path);

}  // namespace flexmoor::app
