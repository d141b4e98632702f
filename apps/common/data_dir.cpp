#include "apps/common/data_dir.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace flexmoor::app {
namespace {

namespace fs = std::filesystem;

// The file this code was loaded from: libflexmoor.so.<version> (or a program linking the code
// in), its links resolved.
fs::path loadedFrom() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&dataDir), &info) == 0 || info.dli_fname == nullptr)
    throw std::runtime_error("cannot tell which file libflexmoor was loaded from (dladdr)");
  std::error_code ec;
  const fs::path file = fs::canonical(info.dli_fname, ec);
  return ec ? fs::path(info.dli_fname) : file;
}

}  // namespace

fs::path dataDir() {
  const char* set = std::getenv("FLEXMOOR_DATA_DIR");
  if (set != nullptr && *set != '\0') {
    const fs::path dir(set);
    if (!fs::is_directory(dir / "cases"))
      throw std::runtime_error("FLEXMOOR_DATA_DIR=" + dir.string() +
                               " holds no cases/ folder (expected cases/ and plot/ in it)");
    return dir;
  }
  const fs::path library = loadedFrom();
  const fs::path dir = (library.parent_path() / FLEXMOOR_DATA_FROM_LIBRARY).lexically_normal();
  if (!fs::is_directory(dir / "cases"))
    throw std::runtime_error("the data folder is missing: no " + (dir / "cases").string() +
                             " (share/flexmoor beside " + library.string() +
                             "); set FLEXMOOR_DATA_DIR to a folder holding cases/ and plot/");
  return dir;
}

fs::path casesDir() { return fs::canonical(dataDir() / "cases"); }

fs::path plotScript() {
  const fs::path script = dataDir() / "plot" / "flexmoor_plot.py";
  if (!fs::is_regular_file(script))
    throw std::runtime_error("the figure script " + script.string() +
                             " is missing (FLEXMOOR_DATA_DIR, when set, must hold plot/ too)");
  return script;
}

}  // namespace flexmoor::app
