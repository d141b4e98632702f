#pragma once
// A Case from specifications stated in code (apps/problem/case_spec.hpp): the model built as the
// case reader builds it (buildMesh, then buildConditions), its equations numbered. What a case
// file's checks would refuse is refused here too, as far as the specifications tell:
// std::invalid_argument naming what is wrong (an element or support on a node that is not there,
// no element, nothing free to solve for, no step).
#include "apps/problem/case.hpp"
#include "apps/problem/case_spec.hpp"

namespace flexmoor::app {

Case buildCase(const CaseSpec& spec);

}  // namespace flexmoor::app
