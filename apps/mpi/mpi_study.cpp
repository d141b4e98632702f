#include "apps/mpi/mpi_study.hpp"

#include <mpi.h>

#include <cstdlib>
#include <iostream>
#include <sstream>

#include "apps/case/diagnostics.hpp"
#include "apps/run/run_case.hpp"
#include "apps/study/run_study.hpp"
#include "apps/study/study_reader.hpp"

namespace flexmoor::app {

bool launchedByMpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr;
}

int runStudyUnderMpi(const std::string& study_file, const std::string& dir, int workers,
                     std::ostream& log) {
  MPI_Init(nullptr, nullptr);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int code = kSuccess;
  try {
    const Study study = readStudy(study_file);
    if (rank == 0)
      log << "study: " << study.members.size() << " members over " << ranks << " MPI ranks\n";
    runStudyMembers(study, dir, workers > 0 ? workers : 1, rank, ranks, log);
    MPI_Barrier(MPI_COMM_WORLD);  // every rank's members have their outcome on disk
    if (rank == 0) code = finishStudy(study, dir, log);
  } catch (const CaseError& e) {
    if (rank == 0) std::cerr << e.what() << "\n";
    code = kBadInput;  // every rank read the same study, so every rank is here
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: rank " << rank << ": " << e.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, kRunFailed);
  }
  MPI_Bcast(&code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Finalize();
  return code;
}

}  // namespace flexmoor::app
