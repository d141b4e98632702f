#include "tests/support/in_process_run.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "apps/case/case_reader.hpp"
#include "tests/support/case_files.hpp"

namespace flexmoor::test {

double InProcessRun::value(const std::string& key) const {
  for (const auto& [name, v] : summary)
    if (name == key) return v;
  ADD_FAILURE() << "no summary value " << key << "\n" << log;
  return 0.0;
}

InProcessRun runCaseInProcess(const std::string& name, const std::string& text) {
  const app::Case c = app::readCase(writeCase(name + ".yaml", text));
  std::ostringstream log, diag;
  app::Simulation simulation(c, log, diag);
  const app::SimulationResult r = simulation.run();
  return {r.exit_code, r.summary, log.str() + diag.str()};
}

}  // namespace flexmoor::test
