#pragma once
// What sees every accepted state of a dynamic step (simulation.hpp), not only the records the
// sinks get (every output_every-th): a series that needs every time step, as a study's collect:.
#include "libstruct/model/assembler.hpp"
#include "libstruct/model/state.hpp"

namespace flexmoor::app {

class StateObserver {
 public:
  virtual ~StateObserver() = default;
  // Step `step` (0-based) of the case: its first state (its start acceleration known), then every
  // accepted state in time order; `assembler` is the step's, for what a quantity needs.
  virtual void accepted(int step, const model::State& s, const model::Assembler& assembler) = 0;
};

}  // namespace flexmoor::app
