#pragma once
// One solved state as the writers see it: the state, its element results and support reactions,
// labelled with the step it closes (a stage record) or, in a dynamic step, the time it reached.
#include <string>
#include <string_view>
#include <vector>

#include "libstruct/element/element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/model/state.hpp"

namespace flexmoor::app {

// A step that did not converge writes its last converged state as a record named after the step
// with this added.
inline constexpr std::string_view kLastConvergedSuffix = " (last converged)";

struct ResultFrame {
  int step_index = 0;     // 0-based index of the analysis step in the case
  std::string step_name;  // "relax", "static", ...
  // A stage record (netcdf_writer.hpp): the state that closes a step that is not dynamic, or
  // the last converged state of a step that did not converge; else a record of the time axis.
  bool stage = false;
  const model::State* state = nullptr;
  std::vector<element::ElementResult> elements;
  model::NodalField reactions;  // 3 x nodes; zero at free dofs
  // A modes step: natural circular frequencies (rad/s, ascending) and mass-normalised shapes.
  std::vector<double> frequencies;
  std::vector<model::NodalField> mode_shapes;
  // A streamed record handed to a sink that completes results itself
  // (ResultSink::completesResults): its element results and reactions are still to be computed
  // by this assembler from these inputs (completeResults), on the sink's own thread.
  const model::Assembler* pending = nullptr;
  model::ResultInputs inputs;
};

// Computes the element results and reactions of a frame whose results are pending.
inline void completeResults(ResultFrame& frame) {
  if (!frame.pending) return;
  frame.pending->results(*frame.state, frame.inputs, frame.elements, frame.reactions);
  frame.pending = nullptr;
}

}  // namespace flexmoor::app
