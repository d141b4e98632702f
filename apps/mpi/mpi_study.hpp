#pragma once
// A study under mpirun (OpenMPI): the members spread over the ranks, member i to rank
// (i - 1) mod K; each rank runs its own one at a time (in a worker process, as locally:
// member_pool.hpp), then every rank waits at a barrier and rank 0 writes study.nc from the
// members' files (DIR on a file system every rank sees). Built only with FLEXMOOR_MPI. The MPI
// calls are in the module libflexmoor_mpi.so (mpi_ranks.hpp), loaded here only, so that
// `flexmoor run` and a local study neither load libmpi nor start MPI.
#include <ostream>
#include <string>

namespace flexmoor::app {

// Whether this process was started by mpirun: OpenMPI's OMPI_COMM_WORLD_SIZE, or PMIx's
// PMIX_RANK, is in the environment.
bool launchedByMpi();

// Reads and checks the study on every rank (rank 0 reports its problems), runs the rank's
// members on `workers` processes (1 unless -j says otherwise) and, on rank 0, writes study.nc.
// Returns the study's exit code on every rank (run_study.hpp).
int runStudyUnderMpi(const std::string& study_file, const std::string& dir, int workers,
                     std::ostream& log);

}  // namespace flexmoor::app
