#pragma once
// What the tests of libhydro's catenary solve share: OC3-Hywind's mooring line
// (docs/theory.md#oc3-hywind) as its inputs (spans 848.67 m and 250 m, L = 902.2 m,
// w = 698.09 N/m, EA = 384.243e6 N), and the check that a line is refused with a message.
#include <gtest/gtest.h>

#include <string>

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

// The solve refuses `in` with a CatenaryError whose message contains `fragment`.
inline void expectCatenaryError(const hydro::CatenaryLineInputs& in, const std::string& fragment) {
  try {
    hydro::solveCatenary(in);
    ADD_FAILURE() << "no error, expected one with \"" << fragment << "\"";
  } catch (const hydro::CatenaryError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

}  // namespace flexmoor::test
