#include "apps/run/run_case.hpp"

#include <memory>
#include <ostream>

#include "apps/run/case_run.hpp"

namespace flexmoor::app {

RunOutcome runCase(const Case& c, const RunOptions& options, std::ostream& log,
                   std::ostream& diag) {
  std::unique_ptr<CaseRun> run;
  try {
    run = std::make_unique<CaseRun>(c, options, log, diag);
  } catch (const std::exception& e) {  // the run was refused: nothing was written
    diag << "flexmoor: " << e.what() << "\n";
    RunOutcome out;
    out.exit_code = kRunFailed;
    return out;
  }
  return run->run();
}

}  // namespace flexmoor::app
