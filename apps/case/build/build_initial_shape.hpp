#pragma once
// The start of the lines that start on their elastic catenary (apps/problem/catenary_start_spec.hpp)
// on a built model whose supports are on it.
#include <string>
#include <vector>

#include "apps/problem/case.hpp"
#include "apps/problem/catenary_start_spec.hpp"
#include "apps/problem/ocean_spec.hpp"
#include "apps/problem/spec_error.hpp"

namespace flexmoor::app {

// Each line on its catenary: its nodes' start displacements, at load factor 1 (the model's start
// load factor is set to 1 when there are any). A line that cannot start (no gravity along -z, an
// end below the seabed, a span its catenary cannot reach, a node another line's start already
// has) is an error; the others start.
std::vector<SpecError> startOnCatenaries(const std::vector<CatenaryStartSpec>& starts,
                                         const OceanSpec& ocean, Case& c);

// The weight per unstretched length of a line of this section in gravity g, less its buoyancy
// rho_w g pi d^2 / 4 in the ocean's water when it has a Morison diameter d.
double submergedWeightPerLength(const OceanSpec& ocean, double g,
                                const element::CableSection& section, double diameter);

}  // namespace flexmoor::app
