// Runs a named case through an installed libflexmoor: the case is found in the installed
// share/flexmoor/cases, read, and run in process by app::Simulation with no sinks. Prints each
// summary quantity and its value, one a line, and exits with the run's exit code.
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "apps/case/case_reader.hpp"
#include "apps/run/simulation.hpp"

int main(int argc, char** argv) {
  namespace app = flexmoor::app;
  const std::string name = argc > 1 ? argv[1] : "ex8-relaxation-test";
  const app::Case c = app::readCase(app::resolveCasePath(name));
  std::ostringstream progress;
  app::Simulation simulation(c, progress, std::cerr);
  const app::SimulationResult result = simulation.run();
  std::cout << std::setprecision(17);
  for (const auto& [quantity, value] : result.summary)
    std::cout << quantity << " " << value << "\n";
  return result.exit_code;
}
