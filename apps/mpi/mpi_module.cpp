// libflexmoor_mpi.so: the study's MPI calls (mpi_ranks.hpp) through OpenMPI's C API.
#include <mpi.h>

#include "apps/mpi/mpi_ranks.hpp"

namespace {

void init(int* rank, int* ranks) {
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, ranks);
}

void barrier() { MPI_Barrier(MPI_COMM_WORLD); }

int broadcast(int value) {
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

void abortAll(int code) { MPI_Abort(MPI_COMM_WORLD, code); }

void finalize() { MPI_Finalize(); }

const FlexmoorMpiRanks kRanks = {init, barrier, broadcast, abortAll, finalize};

}  // namespace

extern "C" const FlexmoorMpiRanks* flexmoor_mpi_ranks() { return &kRanks; }
