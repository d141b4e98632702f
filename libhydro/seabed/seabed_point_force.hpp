#pragma once
// The seabed contact at a point as the load-point interface's PointForce: what the line and the
// node adapters (seabed_line_load.hpp, seabed_node_load.hpp) both return.
#include "libhydro/seabed/seabed_contact.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::hydro {

inline model::PointForce seabedPointForce(const SeabedPointLoad& s, bool jacobians) {
  model::PointForce out;
  out.force = s.force;
  if (!jacobians) return out;
  out.d_position = s.d_position;
  out.d_velocity = s.d_velocity;
  return out;
}

}  // namespace flexmoor::hydro
