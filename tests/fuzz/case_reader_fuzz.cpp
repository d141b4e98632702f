// libFuzzer target of the case reader: any bytes given to readCase must end in a Case
// or in a CaseError (or another std::exception) naming what is wrong. A crash, a sanitizer
// report, a leak, a time-out or a blow-up in memory is a finding. scripts/fuzz.sh builds and
// runs it with the shipped cases as the seed corpus.
//
// The reader reads files only, so each input goes through one temporary file of this process in
// /dev/shm (memory, not disk).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "apps/case/case_reader.hpp"
#include "apps/problem/case_error.hpp"

namespace {

// The file's path; removed when the process exits.
struct InputFile {
  std::string path =
      "/dev/shm/flexmoor-fuzz-" + std::to_string(static_cast<long>(getpid())) + ".yaml";
  ~InputFile() { std::remove(path.c_str()); }
};

const std::string& inputPath() {
  static const InputFile file;
  return file.path;
}

bool writeInput(const uint8_t* data, size_t size) {
  FILE* f = std::fopen(inputPath().c_str(), "wb");
  if (!f) return false;
  const bool written = std::fwrite(data, 1, size, f) == size;
  return std::fclose(f) == 0 && written;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (!writeInput(data, size)) {
    std::perror(inputPath().c_str());
    std::abort();  // a harness that cannot write its input must not report clean runs
  }
  try {
    flexmoor::app::readCase(inputPath());
  } catch (const flexmoor::app::CaseError&) {
    // the expected outcome of a bad file
  } catch (const std::exception&) {
    // any other error the reader reports by exception is a handled outcome too
  }
  return 0;
}
