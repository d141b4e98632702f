#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "apps/problem/source_location.hpp"
#include "libstruct/solve/modal.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::app {

// One analysis step of a case (relax, static, modes or dynamic) and the records it writes.
struct StepSpec {
  enum class Kind { Relax, Static, Modes, Dynamic };
  Kind kind = Kind::Static;
  std::string name;  // "relax", "static", "modes", "dynamic", or the step's own `name:`
  solve::RelaxationOptions relax;
  solve::StaticOptions statics;
  solve::ModalOptions modes;
  solve::DynamicOptions dynamic;
  int output_every = 1;  // dynamic, fixed steps: write every N-th accepted time step (and the last)
  // Dynamic, adaptive steps: write a record every output_interval of the step's time (interpolated
  // between the steps around it) and its last state.
  double output_interval = 0.0;
  // Supports let go at the start of the step (node, component): a held buoy released. They stay
  // free in the steps after.
  std::vector<std::pair<int, int>> release;
  SourceLocation where;

  bool adaptive() const { return kind == Kind::Dynamic && dynamic.adaptive.has_value(); }
  // A dynamic step's time: its duration, or the sum of its schedule's dt x steps; 0 for the other
  // kinds.
  double duration() const {
    if (adaptive()) return dynamic.adaptive->duration;
    double t = 0.0;
    if (kind == Kind::Dynamic)
      for (const solve::TimeSegment& segment : dynamic.schedule) t += segment.dt * segment.steps;
    return t;
  }
  // The records a dynamic step streams: every output_every-th of its time steps (about: the last
  // one is always written), or one every output_interval; 0 for the other kinds.
  long streamedRecords() const {
    if (adaptive()) return std::lround(duration() / output_interval);
    long steps = 0;
    if (kind == Kind::Dynamic)
      for (const solve::TimeSegment& segment : dynamic.schedule) steps += segment.steps;
    return steps / std::max(1, output_every);
  }
};

// The longest step name a case may give: the results' netCDF holds names in fixed rows of
// this many characters (name_strlen, netcdf_writer.hpp).
inline constexpr size_t kMaxNameLength = 128;

}  // namespace flexmoor::app
