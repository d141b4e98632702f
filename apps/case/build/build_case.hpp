#pragma once
// A Case from specifications stated in code (apps/problem/case_spec.hpp): the model built as the
// case reader builds it (buildMesh, buildConditions, its equations numbered, the checks of a
// case file's built model (check/model_checks.hpp), the lines started on their catenaries, then
// buildOcean). What a case file would be refused for is refused here: std::invalid_argument with
// every reason, one a line (an element, support, body or load on a node or element that is not
// there, the ocean's loads without water, no element, nothing free to solve for, no step; a
// collapsed element, a mechanism, a step that needs a mass the model lacks, a node below the
// seabed, Morison loads on what is not a cable; a line that cannot start on its catenary). The
// checks' warnings go to the Case's, and an adaptive step without dt_max gets the bound a case
// file's would.
#include "apps/problem/case.hpp"
#include "apps/problem/case_spec.hpp"

namespace flexmoor::app {

Case buildCase(const CaseSpec& spec);

}  // namespace flexmoor::app
