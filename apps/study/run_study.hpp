#pragma once
// `flexmoor study`: a checked study's members run (those not complete already with their present
// case text), on local worker processes (member_pool.hpp) or, under mpirun, spread over the MPI
// ranks (mpi_study.hpp); then DIR/study.nc from every member's outcome (study_file.hpp).
#include <ostream>
#include <string>

#include "apps/study/study.hpp"

namespace flexmoor::app {

struct StudyOptions {
  std::string output_dir;
  int workers = 0;  // 0: the machine's cores
};

// The members that `rank` of `ranks` runs: member i (1-based) goes to rank (i - 1) mod ranks; the
// complete ones are skipped (counted in `skipped`).
std::vector<const StudyMember*> membersToRun(const Study& study, const std::string& dir, int rank,
                                             int ranks, int& skipped, int& assigned);

// Runs the members of `rank` of `ranks` (0 of 1 without MPI) on `workers` processes; returns how
// many failed.
int runStudyMembers(const Study& study, const std::string& dir, int workers, int rank, int ranks,
                    std::ostream& progress);

// The exit code of a study: 0 when every member is complete, 4 when some failed (study.nc
// records which and why). Writes study.nc and says where it is.
int finishStudy(const Study& study, const std::string& dir, std::ostream& log);

// Local: runStudyMembers on every member, then finishStudy, holding DIR/.study.lock (a second
// study into DIR at once is refused: std::runtime_error).
int runStudy(const Study& study, const StudyOptions& options, std::ostream& log);

}  // namespace flexmoor::app
