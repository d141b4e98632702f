#pragma once
// A state between two accepted time steps, for output at times the steps do not land on: the
// displacement on the cubic Hermite polynomial through u and u' at both ends (C1 in time, exact
// for a motion of constant jerk, the order of the Newmark step itself), its derivative for the
// velocity, the acceleration linear between the two. Element results computed from such a state
// are those of its geometry, consistent with each other as a step's are.
#include "libstruct/model/state.hpp"

namespace flexmoor::solve {

// The state at time t, a.time <= t <= b.time (a.time < b.time), of the step from a to b. Its
// load factor and stillness are b's; it carries no motion record (no time step continues from it).
model::State interpolate(const model::State& a, const model::State& b, double t);

}  // namespace flexmoor::solve
