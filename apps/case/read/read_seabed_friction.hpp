#pragma once
// seabed: friction: of a case (read_hydro.cpp's seabed:), by its law (libhydro/seabed/
// seabed_friction.hpp):
//   friction: 0.5                      flexmoor's Coulomb law with a smooth start, with
//   slip_speed: 0.01 m/s               its slip speed (default 0.01 m/s)
//   friction: {law: coulomb, coefficient: 0.5, slip_speed: 0.01 m/s}   the same
//   friction: {law: moordyn, coefficient: 0.5, damping: 200 N*s/m, static_dynamic_scale: 1}
//                                      MoorDyn's FrictionCoefficient, FricDamp (its default 200
//                                      N*s/m, at each of MoorDyn's nodes: spread over a line's
//                                      node spacing) and StatDynFricScale (default 1)
#include "apps/case/case_builder.hpp"
#include "libhydro/seabed/seabed_contact.hpp"

namespace flexmoor::app {

// Fills the friction of `bed` from the seabed: map's fields; false when something is wrong
// (reported).
bool readSeabedFriction(CaseBuilder& b, const Fields& seabed, hydro::SeabedProperties& bed);

}  // namespace flexmoor::app
