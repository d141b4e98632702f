#pragma once
// The value of a declared summary quantity in the frame that closes its step.
#include "apps/case/case.hpp"
#include "apps/output/result_frame.hpp"

namespace flexmoor::app {

// Displacement, position (reference + displacement), reaction component, reaction magnitude,
// end tension or the largest end tension over all elements, times spec.scale. Throws std::out_of_range when the spec names a node, element, end or component the
// model or frame does not have.
double evaluateSummary(const SummarySpec& spec, const model::Model& model,
                       const ResultFrame& frame);

}  // namespace flexmoor::app
