#pragma once
// The few MPI calls a study makes, as a C table that the module libflexmoor_mpi.so (built from
// mpi_module.cpp with FLEXMOOR_MPI, the only code that links OpenMPI) hands to the flexmoor
// command. The command loads the module with dlopen only when mpirun started it
// (mpi_study.hpp), so `flexmoor run` and a local study neither load nor need libmpi.
extern "C" {

struct FlexmoorMpiRanks {
  void (*init)(int* rank, int* ranks);  // MPI_Init, then this rank and the count
  void (*barrier)();                    // MPI_Barrier on MPI_COMM_WORLD
  int (*broadcast)(int value);          // rank 0's value, on every rank
  void (*abort)(int code);              // MPI_Abort: every rank ends
  void (*finalize)();
};

// The module's one entry point.
const FlexmoorMpiRanks* flexmoor_mpi_ranks();
}
