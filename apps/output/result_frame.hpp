#pragma once
// One solved state as the writers see it: the state, its element results and support reactions,
// labelled with the step it closes (or, in a dynamic step, the time it reached).
#include <string>
#include <string_view>
#include <vector>

#include "libstruct/element/element.hpp"
#include "libstruct/model/state.hpp"

namespace flexmoor::app {

// A step that did not converge writes its last converged state as a record named after the step
// with this added.
inline constexpr std::string_view kLastConvergedSuffix = " (last converged)";

struct ResultFrame {
  int step_index = 0;     // 0-based index of the analysis step in the case
  std::string step_name;  // "relax", "static", ...
  const model::State* state = nullptr;
  std::vector<element::ElementResult> elements;
  model::NodalField reactions;  // 3 x nodes; zero at free dofs
  // A modes step: natural circular frequencies (rad/s, ascending) and mass-normalised shapes.
  std::vector<double> frequencies;
  std::vector<model::NodalField> mode_shapes;
};

}  // namespace flexmoor::app
