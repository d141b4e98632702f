#include "apps/mpi/mpi_study.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "apps/mpi/mpi_ranks.hpp"
#include "apps/problem/case_error.hpp"
#include "apps/run/run_case.hpp"
#include "apps/study/run_study.hpp"
#include "apps/study/study_reader.hpp"

namespace flexmoor::app {
namespace {

// libflexmoor_mpi.so beside the running binary: in bin/ of the build and of an installation
// (cmake/install.cmake), wherever either is moved to.
const FlexmoorMpiRanks& loadRanks() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path module = self.parent_path() / "libflexmoor_mpi.so";
  // RTLD_GLOBAL: OpenMPI's own components, loaded by MPI_Init, resolve libmpi's symbols.
  if (void* handle = dlopen(module.c_str(), RTLD_NOW | RTLD_GLOBAL)) {
    using Entry = const FlexmoorMpiRanks* (*)();
    if (auto entry = reinterpret_cast<Entry>(dlsym(handle, "flexmoor_mpi_ranks"))) return *entry();
  }
  const char* why = dlerror();
  throw std::runtime_error("started by mpirun, but the MPI module cannot be loaded (" +
                           module.string() + ": " + (why ? why : "no flexmoor_mpi_ranks") + ")");
}

}  // namespace

bool launchedByMpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr;
}

int runStudyUnderMpi(const std::string& study_file, const std::string& dir, int workers,
                     std::ostream& log) {
  const FlexmoorMpiRanks& mpi = loadRanks();
  int rank = 0, ranks = 1;
  mpi.init(&rank, &ranks);
  int code = kSuccess;
  try {
    const Study study = readStudy(study_file);
    if (rank == 0)
      log << "study: " << study.members.size() << " members over " << ranks << " MPI ranks\n";
    runStudyMembers(study, dir, workers > 0 ? workers : 1, rank, ranks, log);
    mpi.barrier();  // every rank's members have their outcome on disk
    if (rank == 0) code = finishStudy(study, dir, log);
  } catch (const CaseError& e) {
    if (rank == 0) std::cerr << e.what() << "\n";
    code = kBadInput;  // every rank read the same study, so every rank is here
  } catch (const std::exception& e) {
    std::cerr << "flexmoor: rank " << rank << ": " << e.what() << "\n";
    mpi.abort(kRunFailed);
  }
  code = mpi.broadcast(code);
  mpi.finalize();
  return code;
}

}  // namespace flexmoor::app
