#pragma once
// OC3-Hywind's mooring line (../shared/reference/ocean-cases.md) as inputs of libhydro's
// catenary solve: spans 848.67 m and 250 m, L = 902.2 m, w = 698.09 N/m, EA = 384.243e6 N.
#include "libhydro/mooring/catenary_line.hpp"

namespace flexmoor::test {

inline hydro::CatenaryLineInputs oc3CatenaryInputs() {
  hydro::CatenaryLineInputs in;
  in.horizontal_span = 853.87 - 5.2;
  in.vertical_span = 320.0 - 70.0;
  in.unstretched_length = 902.2;
  in.weight = 698.09;
  in.axial_stiffness = 384.243e6;
  return in;
}

}  // namespace flexmoor::test
