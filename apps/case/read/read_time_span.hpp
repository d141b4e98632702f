#pragma once
// The time a dynamic step covers and where its records fall:
//
//   {duration: 600 s}                        steps chosen by their accuracy (adaptive), records
//                                            every duration / 1000
//   {duration: 600 s, output: 0.1 s}         the same, records every 0.1 s (interpolated between
//                                            the steps that pass them)
//   {dt: 0.1 s, duration: 600 s}             fixed steps, 6000 of them
//   {dt: 0.1 s, steps: 6000}                 the same
//   {schedule: [{dt: 0.02 s, steps: 50}, {dt: 0.05 s, steps: 40}]}
//
// Adaptive steps take step_tolerance (the local error, default 0.01), dt_max (default: a tenth
// of the shortest period that drives the model, model_checks.cpp, or the duration) and dt_min;
// fixed steps take output_every (a record every N-th step) or output (a whole number of steps).
#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

// The keys above of the dynamic step `f` into step.dynamic's schedule or adaptive, and
// step.output_every / step.output_interval.
void readTimeSpan(CaseBuilder& b, Fields& f, StepSpec& step);

// The keys readTimeSpan reads.
const std::vector<std::string>& timeSpanKeys();

}  // namespace flexmoor::app
