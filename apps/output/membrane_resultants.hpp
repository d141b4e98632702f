#pragma once
// In-plane principal stress resultants of a membrane element (force per current length), from
// the principal resultants at its integration points, averaged; shared by summary.json, netCDF
// and VTK so that all three report the same numbers.
#include <optional>
#include <utility>

#include "libstruct/element/element.hpp"

namespace flexmoor::app {

// {larger, smaller}; nullopt for an element without membrane resultants (a cable, a spring).
std::optional<std::pair<double, double>> principalResultants(const element::ElementResult& r);

}  // namespace flexmoor::app
