#pragma once
// The front of a wave train (Example 9): still water ahead of a front that starts at distance x0
// along the wave's heading and moves with the group speed (the speed of the wave energy) or the
// phase speed, and a smooth ramp of the amplitude over `ramp_periods` wave periods behind it, so
// that the structure is not struck impulsively. The ramp is 3 s^2 - 2 s^3 in the distance behind
// the front, s in [0, 1] over ramp_periods T c_front.
#include "libhydro/waves/wave_component.hpp"

namespace flexmoor::hydro {

struct WaveFront {
  enum class Speed { Group, Phase };
  double start = 0.0;  // x0: front position along the heading at t = 0
  Speed speed = Speed::Group;
  double ramp_periods = 1.0;  // 0: the full amplitude right behind the front
};

// The front as one component sees it: its speed (group or phase, from the dispersion relation)
// and the ramp's length, computed once when the sea is built.
struct ComponentFront {
  double start = 0.0, speed = 0.0, ramp = 0.0;
};
ComponentFront componentFront(const WaveFront& front, const WaveComponent& c, double depth,
                              double g);

// The amplitude factor E in [0, 1] of the component at distance xi along its heading and time
// t, with dE/dt, dE/dxi and d(dE/dt)/dxi (wave_component.hpp).
Envelope frontEnvelope(const ComponentFront& front, double xi, double t);

}  // namespace flexmoor::hydro
