#pragma once
// What a checkpoint of a simulation's dynamic step holds (Simulation::save): for simulation.cpp,
// which takes and restores it, and checkpoint_file.cpp, which writes it to a file and reads it.
#include "apps/output/summary_series.hpp"
#include "apps/run/record_interpolator.hpp"
#include "apps/run/simulation.hpp"
#include "libstruct/solve/time_integrator.hpp"

namespace flexmoor::app {

struct Simulation::Checkpoint {
  const Simulation* simulation;
  int step;  // the dynamic step's index in the case
  solve::IntegratorCheckpoint integrator;
  int accepted, output_index;
  double next_report, last_record_time;
  SummarySeries series;
  RecordInterpolator between;
};

}  // namespace flexmoor::app
