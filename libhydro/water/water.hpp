#pragma once
// The still water a model sits in: density, depth of the flat bed below the mean level z = 0, and
// gravity (z up). Depth may be +infinity (deep water).
namespace flexmoor::hydro {

struct Water {
  double density = 1025.0;  // rho_w
  double depth = 0.0;       // h: the bed is at z = -h
  double gravity = 9.80665;
};

}  // namespace flexmoor::hydro
