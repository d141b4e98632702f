#pragma once
// Puts a case's ocean (apps/problem/ocean_spec.hpp) on its built model: the sea of its water,
// waves and current kept in the Case (sea, sea_origin, seabed), Morison loads on the cable
// elements it names (one load per length measure in use), the bodies' loads at their nodes, the
// incident wave pressure on membranes, and seabed contact over the lines' hydrodynamic diameters
// and the bodies' projected areas (the Case's seabed_contact). Nothing without water.
#include "apps/problem/case.hpp"
#include "apps/problem/ocean_spec.hpp"

namespace flexmoor::app {

void buildOcean(const OceanSpec& spec, Case& c);

}  // namespace flexmoor::app
