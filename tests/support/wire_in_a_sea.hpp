#pragma once
// The submerged wire (submerged_wire.hpp) pulled 1 cm taut, in a JONSWAP sea (Hs 2 m, Tp 8 s, 50
// equal bins, seed 77), run by `flexmoor run` for the figure tests: relaxed to its still-water
// equilibrium, then `steps` time steps of 0.25 s, every step a record. The run is required to
// converge without a step cut, so that its records are evenly spaced: the figures drawn from it
// do not depend on how the solver copes with a hard problem.
#include <filesystem>
#include <string>

namespace flexmoor::test {

// Runs the wire into a scratch directory of `name` and this process; returns its netCDF.
std::filesystem::path runWireInASea(const std::string& name, int steps);

}  // namespace flexmoor::test
