#include "libstruct/solve/newmark.hpp"

#include "libstruct/solve/time_integrator.hpp"

namespace flexmoor::solve {

DynamicReport integrate(const model::Assembler& assembler, model::State& state,
                        const DynamicOptions& options, const SolveLog& log,
                        const std::function<void(const model::State&)>& on_step) {
  TimeIntegrator integrator(assembler, options, log);
  integrator.start(state);
  if (options.adaptive)
    integrator.advanceTo(state, state.time + options.adaptive->duration, on_step);
  for (const TimeSegment& segment : options.schedule)
    for (int k = 0; k < segment.steps; ++k) integrator.step(state, segment.dt, on_step);
  return integrator.report();
}

}  // namespace flexmoor::solve
