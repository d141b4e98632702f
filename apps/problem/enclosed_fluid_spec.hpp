#pragma once
// A liquid that fills membranes (libhydro/loads/enclosed_fluid.hpp) as a specification: what a
// case file's `loads: enclosed_fluid:` resolves to once its water and gravity are read, and what a
// program fills to state one without a case file (case_spec.hpp). buildEnclosedFluids
// (apps/case/build/build_enclosed_fluid.hpp) measures its wall on the built model and puts its
// pressure and its mass, lumped at the wall's nodes, there.
#include <string>
#include <vector>

#include "libhydro/loads/enclosed_fluid.hpp"

namespace flexmoor::app {

struct EnclosedFluidSpec {
  std::vector<int> elements;   // the membranes that hold it, 0-based model elements
  hydro::EnclosedFluid fluid;  // its density, gauge pressure at an elevation and gravity
  int line = 0;                // of the case file that states it (0: none)
  std::string where;           // names it in messages: "loads.enclosed_fluid[0]"
};

}  // namespace flexmoor::app
