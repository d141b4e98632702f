#pragma once
// One study member's run, in the process that calls it (a worker process of the study runner):
// its case built again from the study (the same as the study reader checked), run with
// runCase into DIR/members/NNNN/ (no VTK files, no figure), its collected series written to
// series.nc and, last, the member marked complete.
#include <string>

#include "apps/study/study.hpp"

namespace flexmoor::app {

// The run's exit code (run_case.hpp's ExitCode): progress to DIR/members/NNNN/run.log by the
// caller's redirection of stdout, diagnoses to stderr.
int runMember(const Study& study, const StudyMember& member, const std::string& dir);

}  // namespace flexmoor::app
