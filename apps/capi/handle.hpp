#pragma once
// A handle of the C interface (flexmoor.h) and what every entry point shares: the table of open
// handles, the guard that turns what the C++ side throws into an error code and the handle's
// message, and the checks of a call's arguments and order.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "apps/capi/flexmoor.h"
#include "apps/capi/log_lines.hpp"
#include "apps/host/coupling.hpp"
#include "apps/problem/case.hpp"
#include "apps/problem/case_error.hpp"
#include "apps/run/case_run.hpp"
#include "apps/run/simulation.hpp"
#include "libstruct/solve/solve_log.hpp"

// A checkpoint (flexmoor_save): the simulation's and the host's side of the state.
struct flexmoor_checkpoint {
  const flexmoor_simulation* owner;
  std::shared_ptr<const flexmoor::app::Simulation::Checkpoint> simulation;
  std::vector<flexmoor::model::CoupledMotion::Sample> coupled;
  double origin, constant_dt;  // the host's time grid (flexmoor_simulation)
  long steps_at_constant_dt;
};

// What a handle stands for: the case, the bodies the host drives, the run and the last error.
struct flexmoor_simulation {
  enum class Phase { Created, Stepping, Finished, Broken };
  Phase phase = Phase::Created;
  std::string error;
  flexmoor::capi::LogStream log{0}, diag{1};
  std::unique_ptr<flexmoor::app::Case> c;
  std::vector<std::string> coupled_names;
  std::vector<int> coupled_dofs;  // of each of coupled_names
  std::unique_ptr<flexmoor::app::Coupling> bodies;
  std::optional<std::string> output_dir;
  std::unique_ptr<flexmoor::app::CaseRun> run;      // with results files
  std::unique_ptr<flexmoor::app::Simulation> bare;  // without
  flexmoor::app::Simulation* simulation = nullptr;  // the one of the two in use
  bool failed_step = false;  // the last step failed: a restore comes next (or finish)
  // A host stepping at a constant dt reaches origin + n dt, computed, not summed: the records'
  // times are then on its grid to the last bit (as the command's schedule is).
  double origin = 0.0, constant_dt = 0.0;
  long steps_at_constant_dt = 0;
  std::vector<std::pair<std::string, double>> summary;
  std::vector<const flexmoor::app::CaseLine*> lines;  // the named lines that are not segments
};

namespace flexmoor::capi {

// A wrong call: the message is the handle's, the code FLEXMOOR_BAD_CALL.
struct BadCall : std::logic_error {
  using std::logic_error::logic_error;
};

// The open handle's simulation, or null for a null, closed or unknown handle.
flexmoor_simulation* findHandle(flexmoor_t handle);
// A new handle in the table; its removal (flexmoor_close) hands it back.
flexmoor_t addHandle(std::unique_ptr<flexmoor_simulation> s);
std::unique_ptr<flexmoor_simulation> removeHandle(flexmoor_t handle);

// Runs `body` on the handle's simulation: its exceptions become codes and the handle's message.
template <class Body>
int guarded(flexmoor_t handle, Body&& body) {
  flexmoor_simulation* h = findHandle(handle);
  if (!h) return FLEXMOOR_BAD_CALL;
  h->error.clear();
  h->diag.lines.clear();
  try {
    return body(*h);
  } catch (const BadCall& e) {
    h->error = e.what();
    return FLEXMOOR_BAD_CALL;
  } catch (const app::CaseError& e) {
    for (const std::string& m : e.messages()) h->error += (h->error.empty() ? "" : "\n") + m;
    return FLEXMOOR_BAD_INPUT;
  } catch (const solve::ConvergenceError& e) {
    h->error = std::string("did not converge: ") + e.what();
    return FLEXMOOR_NOT_CONVERGED;
  } catch (const std::bad_alloc&) {
    h->error = "out of memory";
    h->phase = flexmoor_simulation::Phase::Broken;
    return FLEXMOOR_FAILED;
  } catch (const std::exception& e) {
    h->error = e.what();
    return FLEXMOOR_FAILED;
  } catch (...) {
    h->error = "an unknown failure";
    return FLEXMOOR_FAILED;
  }
}

// BadCall(what) unless `condition`.
void require(bool condition, const std::string& what);
// BadCall naming the call, when the handle is not in `phase`.
void requirePhase(const flexmoor_simulation& h, flexmoor_simulation::Phase phase, const char* call);
// BadCall before init: no state yet.
void requireState(const flexmoor_simulation& h, const char* call);
// The host's count of coupled values against the case's.
void requireCount(const flexmoor_simulation& h, int count, const char* call);
// The named line `line` (0-based) and its node `node`'s model node; BadCall when out of range.
const app::CaseLine& lineAt(const flexmoor_simulation& h, int line, const char* call);
int lineNode(const flexmoor_simulation& h, int line, int node, const char* call);

}  // namespace flexmoor::capi
