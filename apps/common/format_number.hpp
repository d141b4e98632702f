#pragma once
// Numbers as flexmoor's messages show them.
#include <string>

namespace flexmoor::app {

// A number as messages show it: %g style with ten significant digits ("1e+13", "0.3", "2.5",
// "1.0000001"), never %f's six fixed decimals ("10000000000000.000000", "0.000000").
std::string formatNumber(double value);

}  // namespace flexmoor::app
