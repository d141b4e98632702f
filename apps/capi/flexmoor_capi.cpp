// The C interface (flexmoor.h) over the C++ simulation: a handle owns its case, its coupled
// bodies and its run; every entry point catches what the C++ side throws and turns it into an
// error code and the handle's message.
#include "apps/capi/flexmoor.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <optional>
#include <string>
#include <vector>

#include "apps/capi/log_lines.hpp"
#include "apps/case/case_reader.hpp"
#include "apps/case/diagnostics.hpp"
#include "apps/host/coupled_bodies.hpp"
#include "apps/run/case_run.hpp"
#include "apps/run/simulation.hpp"
#include "libstruct/solve/solve_log.hpp"

using namespace flexmoor;

struct flexmoor_checkpoint {
  const flexmoor_simulation* owner;
  std::shared_ptr<const app::Simulation::Checkpoint> simulation;
  std::vector<model::CoupledMotion::Sample> coupled;
  double origin, constant_dt;  // the host's time grid (flexmoor_simulation)
  long steps_at_constant_dt;
};

struct flexmoor_simulation {
  enum class Phase { Created, Stepping, Finished, Broken };
  Phase phase = Phase::Created;
  std::string error;
  capi::LogStream log{0}, diag{1};
  std::unique_ptr<app::Case> c;
  std::vector<std::string> coupled_names;
  std::unique_ptr<app::CoupledBodies> bodies;
  std::optional<std::string> output_dir;
  std::unique_ptr<app::CaseRun> run;         // with results files
  std::unique_ptr<app::Simulation> bare;     // without
  app::Simulation* simulation = nullptr;     // the one of the two in use
  bool failed_step = false;  // the last step failed: a restore comes next (or finish)
  // A host stepping at a constant dt reaches origin + n dt, computed, not summed: the records'
  // times are then on its grid to the last bit (as the command's schedule is).
  double origin = 0.0, constant_dt = 0.0;
  long steps_at_constant_dt = 0;
  std::vector<std::pair<std::string, double>> summary;
  std::vector<const app::CaseLine*> lines;   // the named lines that are not segments
};

namespace {

// A wrong call: the message is the handle's, the code FLEXMOOR_BAD_CALL.
struct BadCall : std::logic_error {
  using std::logic_error::logic_error;
};

const char kUnknownHandle[] =
    "flexmoor: a null, closed or unknown handle (flexmoor_create makes one, flexmoor_close ends "
    "it)";

// The open handles. A handle is a number, never reused, that this table maps to its simulation:
// a call with a closed or made-up handle finds nothing and says so, instead of touching freed
// memory.
class Registry {
 public:
  flexmoor_t add(std::unique_ptr<flexmoor_simulation> s) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const uintptr_t id = next_++;
    open_.emplace(id, std::move(s));
    return reinterpret_cast<flexmoor_t>(id);
  }
  flexmoor_simulation* find(flexmoor_t h) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = open_.find(reinterpret_cast<uintptr_t>(h));
    return found == open_.end() ? nullptr : found->second.get();
  }
  std::unique_ptr<flexmoor_simulation> remove(flexmoor_t h) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = open_.find(reinterpret_cast<uintptr_t>(h));
    if (found == open_.end()) return nullptr;
    std::unique_ptr<flexmoor_simulation> s = std::move(found->second);
    open_.erase(found);
    return s;
  }

 private:
  std::mutex mutex_;
  std::unordered_map<uintptr_t, std::unique_ptr<flexmoor_simulation>> open_;
  uintptr_t next_ = 1;
};

Registry& registry() {
  static Registry r;
  return r;
}

// Runs `body` on the handle's simulation: its exceptions become codes and the handle's message.
template <class Body>
int guarded(flexmoor_t handle, Body&& body) {
  flexmoor_simulation* h = registry().find(handle);
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

void require(bool condition, const std::string& what) {
  if (!condition) throw BadCall(what);
}

void requirePhase(const flexmoor_simulation& h, flexmoor_simulation::Phase phase,
                  const char* call) {
  using Phase = flexmoor_simulation::Phase;
  if (h.phase == phase) return;
  const char* now = h.phase == Phase::Created    ? "before flexmoor_init"
                    : h.phase == Phase::Stepping ? "after flexmoor_init"
                    : h.phase == Phase::Finished ? "after flexmoor_finish"
                                                 : "after a failure that ended the simulation";
  const char* needed = phase == Phase::Created    ? "before flexmoor_init"
                       : phase == Phase::Stepping ? "between flexmoor_init and flexmoor_finish"
                                                  : "after flexmoor_finish";
  throw BadCall(std::string(call) + ": called " + now + " (it is for " + needed + ")");
}

std::string rigidMotionNames(const app::Case& c) {
  std::string list;
  for (const auto& entry : c.rigid_motions) list += (list.empty() ? "" : ", ") + entry.first;
  return list.empty() ? "none" : list;
}

const app::CaseLine& lineAt(const flexmoor_simulation& h, int line, const char* call) {
  require(line >= 0 && line < static_cast<int>(h.lines.size()),
          std::string(call) + ": line " + std::to_string(line) + " out of range (the case has " +
              std::to_string(h.lines.size()) + " lines, 0 to " +
              std::to_string(static_cast<int>(h.lines.size()) - 1) + ")");
  return *h.lines[line];
}

int lineNode(const flexmoor_simulation& h, int line, int node, const char* call) {
  const app::CaseLine& l = lineAt(h, line, call);
  require(node >= 0 && node < static_cast<int>(l.nodes.size()),
          std::string(call) + ": node " + std::to_string(node) + " out of range (line " +
              l.name + " has " + std::to_string(l.nodes.size()) + " nodes)");
  return l.nodes[node];
}

void requireState(const flexmoor_simulation& h, const char* call) {
  require(h.phase == flexmoor_simulation::Phase::Stepping ||
              h.phase == flexmoor_simulation::Phase::Finished,
          std::string(call) + ": no state before flexmoor_init");
}

int create(app::Case c, flexmoor_simulation* h) {
  h->c = std::make_unique<app::Case>(std::move(c));
  for (const app::CaseLine& line : h->c->named_lines)
    if (line.segment_of.empty()) h->lines.push_back(&line);
  return FLEXMOOR_OK;
}

template <class Read>
int createWith(flexmoor_t* handle, Read&& read) {
  if (!handle) return FLEXMOOR_BAD_CALL;
  *handle = nullptr;
  try {
    *handle = registry().add(std::make_unique<flexmoor_simulation>());
  } catch (...) {
    return FLEXMOOR_FAILED;
  }
  return guarded(*handle, [&](flexmoor_simulation& h) { return create(read(), &h); });
}

// The host's count of coupled values against the case's.
void requireCount(const flexmoor_simulation& h, int count, const char* call) {
  const int dofs = app::CoupledBodies::kDofs * static_cast<int>(h.coupled_names.size());
  require(count == dofs, std::string(call) + ": " + std::to_string(count) +
                             " coupled values (expected " + std::to_string(dofs) + ": 6 for each "
                             "coupled body)");
}

}  // namespace

extern "C" {

const char* flexmoor_version(void) { return FLEXMOOR_VERSION; }

int flexmoor_create(const char* path, flexmoor_t* handle) {
  return createWith(handle, [&] {
    require(path != nullptr, "flexmoor_create: a null path");
    std::string resolved;
    try {
      resolved = app::resolveCasePath(path);
    } catch (const std::runtime_error& e) {
      throw app::CaseError({e.what()});
    }
    return app::readCase(resolved);
  });
}

int flexmoor_create_from_yaml(const char* yaml, const char* name, flexmoor_t* handle) {
  return createWith(handle, [&] {
    require(yaml != nullptr, "flexmoor_create_from_yaml: null text");
    return app::readCase(app::loadCaseFromText(yaml, name && *name ? name : "case"));
  });
}

void flexmoor_close(flexmoor_t handle) {
  try {
    // The run's records so far stay in its .partial file; nothing is put in place.
    registry().remove(handle);
  } catch (...) {
  }
}

const char* flexmoor_last_error(flexmoor_t handle) {
  const flexmoor_simulation* h = registry().find(handle);
  return h ? h->error.c_str() : kUnknownHandle;
}

int flexmoor_set_logger(flexmoor_t handle, flexmoor_log_function log, void* user_data) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Created, "flexmoor_set_logger");
    h.log.lines.setCallback(log, user_data);
    h.diag.lines.setCallback(log, user_data);
    return FLEXMOOR_OK;
  });
}

int flexmoor_set_output(flexmoor_t handle, const char* directory) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Created, "flexmoor_set_output");
    require(h.c != nullptr, "flexmoor_set_output: the case was not read");
    require(directory && *directory, "flexmoor_set_output: no directory");
    h.output_dir = directory;
    return FLEXMOOR_OK;
  });
}

int flexmoor_couple(flexmoor_t handle, const char* name) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Created, "flexmoor_couple");
    require(h.c != nullptr, "flexmoor_couple: the case was not read");
    require(name != nullptr, "flexmoor_couple: a null name");
    require(h.c->rigid_motions.count(name),
            std::string("flexmoor_couple: no rigid motion named '") + name + "' in case " +
                h.c->name + " (its rigid motions: " + rigidMotionNames(*h.c) + ")");
    for (const std::string& n : h.coupled_names)
      require(n != name, std::string("flexmoor_couple: '") + name + "' is coupled already");
    std::vector<std::string> names = h.coupled_names;
    names.push_back(name);
    h.coupled_names = names;
    return FLEXMOOR_OK;
  });
}

int flexmoor_coupled_dofs(flexmoor_t handle, int* count) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    require(count != nullptr, "flexmoor_coupled_dofs: a null count");
    *count = app::CoupledBodies::kDofs * static_cast<int>(h.coupled_names.size());
    return FLEXMOOR_OK;
  });
}

int flexmoor_init(flexmoor_t handle, int count, const double* x, const double* xd) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Created, "flexmoor_init");
    require(h.c != nullptr, "flexmoor_init: the case was not read (see flexmoor_create)");
    requireCount(h, count, "flexmoor_init");
    require(count == 0 || (x && xd), "flexmoor_init: null x or xd");
    // From here a failure leaves the handle unusable but for its message and close.
    h.phase = flexmoor_simulation::Phase::Broken;
    h.bodies = std::make_unique<app::CoupledBodies>(*h.c, h.coupled_names);
    h.bodies->hold(h.c->model->startState().time, x, xd, nullptr);
    if (h.output_dir) {
      app::RunOptions options;
      options.output_dir = *h.output_dir;
      options.figure = false;
      options.background_writer = false;  // the host's thread writes: nothing runs behind it
      h.run = std::make_unique<app::CaseRun>(*h.c, options, h.log.stream, h.diag.stream);
      h.simulation = &h.run->simulation();
    } else {
      h.bare = std::make_unique<app::Simulation>(*h.c, h.log.stream, h.diag.stream);
      h.simulation = h.bare.get();
    }
    h.simulation->prepare();
    require(h.simulation->stepping(),
            "flexmoor_init: case " + h.c->name + " has no dynamic step for a host to step");
    h.phase = flexmoor_simulation::Phase::Stepping;
    return FLEXMOOR_OK;
  });
}

int flexmoor_step(flexmoor_t handle, int count, const double* x, const double* xd,
                  const double* xdd, double* f, double* t, double dt) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_step");
    require(!h.failed_step,
            "flexmoor_step: the last step failed; restore a checkpoint (flexmoor_restore) or "
            "finish");
    require(t != nullptr, "flexmoor_step: a null time");
    const double now = h.simulation->time();
    require(*t == now, "flexmoor_step: t = " + std::to_string(*t) +
                           " is not the time reached, " + std::to_string(now) +
                           " (a step starts where the last one ended)");
    require(dt > 0.0 && std::isfinite(dt),
            "flexmoor_step: dt = " + std::to_string(dt) + " (expected a positive time)");
    requireCount(h, count, "flexmoor_step");
    const int dofs = count;
    require(dofs == 0 || (x && xd), "flexmoor_step: null x or xd");
    for (int k = 0; k < dofs; ++k)
      require(std::isfinite(x[k]) && std::isfinite(xd[k]) && (!xdd || std::isfinite(xdd[k])),
              "flexmoor_step: coupled dof " + std::to_string(k) + " is not finite");
    if (dt != h.constant_dt || now != h.origin + h.steps_at_constant_dt * h.constant_dt) {
      h.origin = now;
      h.constant_dt = dt;
      h.steps_at_constant_dt = 0;
    }
    const double end = h.origin + (h.steps_at_constant_dt + 1) * dt;
    h.bodies->next(end, x, xd, xdd);
    try {
      h.simulation->advanceTo(end);
    } catch (...) {
      h.failed_step = true;
      throw;
    }
    if (f && dofs > 0) h.bodies->loads(h.simulation->state(), h.simulation->assembler(), f);
    ++h.steps_at_constant_dt;
    *t = end;
    return FLEXMOOR_OK;
  });
}

int flexmoor_time(flexmoor_t handle, double* t) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requireState(h, "flexmoor_time");
    require(t != nullptr, "flexmoor_time: a null time");
    *t = h.simulation->time();
    return FLEXMOOR_OK;
  });
}

int flexmoor_coupled_loads(flexmoor_t handle, double* f) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_coupled_loads");
    require(f != nullptr || h.bodies->dofs() == 0, "flexmoor_coupled_loads: a null array");
    if (h.bodies->dofs() > 0)
      h.bodies->loads(h.simulation->state(), h.simulation->assembler(), f);
    return FLEXMOOR_OK;
  });
}

int flexmoor_line_count(flexmoor_t handle, int* count) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    require(h.c != nullptr && count != nullptr, "flexmoor_line_count: no case or a null count");
    *count = static_cast<int>(h.lines.size());
    return FLEXMOOR_OK;
  });
}

int flexmoor_line_name(flexmoor_t handle, int line, const char** name) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    require(name != nullptr, "flexmoor_line_name: a null name");
    *name = lineAt(h, line, "flexmoor_line_name").name.c_str();
    return FLEXMOOR_OK;
  });
}

int flexmoor_line_node_count(flexmoor_t handle, int line, int* count) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    require(count != nullptr, "flexmoor_line_node_count: a null count");
    *count = static_cast<int>(lineAt(h, line, "flexmoor_line_node_count").nodes.size());
    return FLEXMOOR_OK;
  });
}

int flexmoor_line_node_position(flexmoor_t handle, int line, int node, double position[3]) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requireState(h, "flexmoor_line_node_position");
    require(position != nullptr, "flexmoor_line_node_position: a null array");
    const int n = lineNode(h, line, node, "flexmoor_line_node_position");
    const Eigen::Vector3d x =
        h.c->model->reference().col(n) + h.simulation->state().displacement.col(n);
    for (int k = 0; k < 3; ++k) position[k] = x[k];
    return FLEXMOOR_OK;
  });
}

int flexmoor_line_node_velocity(flexmoor_t handle, int line, int node, double velocity[3]) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requireState(h, "flexmoor_line_node_velocity");
    require(velocity != nullptr, "flexmoor_line_node_velocity: a null array");
    const int n = lineNode(h, line, node, "flexmoor_line_node_velocity");
    for (int k = 0; k < 3; ++k) velocity[k] = h.simulation->state().velocity(k, n);
    return FLEXMOOR_OK;
  });
}

int flexmoor_line_end_tension(flexmoor_t handle, int line, int end, double* tension) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requireState(h, "flexmoor_line_end_tension");
    require(tension != nullptr, "flexmoor_line_end_tension: a null tension");
    require(end == 0 || end == 1, "flexmoor_line_end_tension: end " + std::to_string(end) +
                                      " (expected 0, the line's start, or 1, its end)");
    const app::CaseLine& l = lineAt(h, line, "flexmoor_line_end_tension");
    require(!l.elements.empty(), "flexmoor_line_end_tension: line " + l.name + " has no elements");
    const int e = end == 0 ? l.elements.front() : l.elements.back();
    *tension = h.simulation->assembler().elementResult(h.simulation->state(), e).end_tension[end];
    return FLEXMOOR_OK;
  });
}

int flexmoor_node_count(flexmoor_t handle, int* count) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    require(h.c != nullptr && count != nullptr, "flexmoor_node_count: no case or a null count");
    *count = h.c->model->nodeCount();
    return FLEXMOOR_OK;
  });
}

int flexmoor_node_positions(flexmoor_t handle, double* positions) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requireState(h, "flexmoor_node_positions");
    require(positions != nullptr, "flexmoor_node_positions: a null array");
    const model::NodalField x = h.c->model->reference() + h.simulation->state().displacement;
    std::copy(x.data(), x.data() + x.size(), positions);
    return FLEXMOOR_OK;
  });
}

int flexmoor_save(flexmoor_t handle, flexmoor_checkpoint_t* checkpoint) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_save");
    require(checkpoint != nullptr, "flexmoor_save: a null checkpoint");
    *checkpoint = new flexmoor_checkpoint{&h,         h.simulation->save(), h.bodies->save(),
                                          h.origin,   h.constant_dt,        h.steps_at_constant_dt};
    return FLEXMOOR_OK;
  });
}

int flexmoor_restore(flexmoor_t handle, flexmoor_checkpoint_t checkpoint) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_restore");
    require(checkpoint != nullptr && checkpoint->owner == &h,
            "flexmoor_restore: the checkpoint is null or of another handle");
    h.simulation->restore(*checkpoint->simulation);
    h.bodies->restore(checkpoint->coupled);
    h.origin = checkpoint->origin;
    h.constant_dt = checkpoint->constant_dt;
    h.steps_at_constant_dt = checkpoint->steps_at_constant_dt;
    h.failed_step = false;
    return FLEXMOOR_OK;
  });
}

void flexmoor_checkpoint_free(flexmoor_checkpoint_t checkpoint) { delete checkpoint; }

int flexmoor_save_file(flexmoor_t handle, const char* path) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_save_file");
    require(path && *path, "flexmoor_save_file: no path");
    require(!h.failed_step, "flexmoor_save_file: the last step failed; restore a checkpoint");
    // The host's side: its coupled motions, then its time grid.
    std::vector<double> host;
    for (const model::CoupledMotion::Sample& s : h.bodies->save())
      host.insert(host.end(), {s.t, s.value, s.rate, s.acceleration, s.has_acceleration ? 1.0 : 0.0});
    host.insert(host.end(), {h.origin, h.constant_dt, static_cast<double>(h.steps_at_constant_dt)});
    h.simulation->saveFile(path, host);
    return FLEXMOOR_OK;
  });
}

int flexmoor_restore_file(flexmoor_t handle, const char* path) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_restore_file");
    require(path && *path, "flexmoor_restore_file: no path");
    const size_t samples = h.bodies->save().size();
    // Checked before anything is restored: a file of other bodies leaves the handle as it was.
    const app::Simulation::CheckpointHost check = [&](const std::vector<double>& host) {
      if (host.size() != 5 * samples + 3)
        throw std::runtime_error(std::string(path) + ": its coupled bodies are not this handle's");
    };
    const std::vector<double> host = h.simulation->restoreFile(path, check);
    std::vector<model::CoupledMotion::Sample> restored;
    for (size_t k = 0; k < samples; ++k) {
      const double* s = &host[5 * k];
      restored.push_back({s[0], s[1], s[2], s[3], s[4] != 0.0});
    }
    h.bodies->restore(restored);
    h.origin = host[5 * samples];
    h.constant_dt = host[5 * samples + 1];
    h.steps_at_constant_dt = static_cast<long>(host[5 * samples + 2]);
    h.failed_step = false;
    return FLEXMOOR_OK;
  });
}

int flexmoor_finish(flexmoor_t handle) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_finish");
    h.phase = flexmoor_simulation::Phase::Finished;
    int code = FLEXMOOR_OK;
    if (h.run) {
      const app::RunOutcome out = h.run->finish();
      h.summary = out.summary;
      code = out.exit_code;
    } else {
      const app::SimulationResult result = h.simulation->finish();
      h.summary = result.summary;
      code = result.exit_code;
    }
    if (code != FLEXMOOR_OK) h.error = h.diag.lines.kept();
    return code;
  });
}

int flexmoor_run(flexmoor_t handle) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Created, "flexmoor_run");
    require(h.c != nullptr, "flexmoor_run: the case was not read (see flexmoor_create)");
    require(h.coupled_names.empty(),
            "flexmoor_run: a body is coupled (a run follows the case's own motions; step it "
            "with flexmoor_init and flexmoor_step instead)");
    h.phase = flexmoor_simulation::Phase::Finished;
    int code = FLEXMOOR_OK;
    if (h.output_dir) {
      app::RunOptions options;
      options.output_dir = *h.output_dir;
      options.figure = false;
      const app::RunOutcome out = app::runCase(*h.c, options, h.log.stream, h.diag.stream);
      h.summary = out.summary;
      code = out.exit_code;
    } else {
      app::Simulation simulation(*h.c, h.log.stream, h.diag.stream);
      const app::SimulationResult result = simulation.run();
      h.summary = result.summary;
      code = result.exit_code;
    }
    if (code != FLEXMOOR_OK) h.error = h.diag.lines.kept();
    return code;
  });
}

int flexmoor_summary_count(flexmoor_t handle, int* count) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Finished, "flexmoor_summary_count");
    require(count != nullptr, "flexmoor_summary_count: a null count");
    *count = static_cast<int>(h.summary.size());
    return FLEXMOOR_OK;
  });
}

int flexmoor_summary_value(flexmoor_t handle, int index, const char** name, double* value) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Finished, "flexmoor_summary_value");
    require(index >= 0 && index < static_cast<int>(h.summary.size()),
            "flexmoor_summary_value: index " + std::to_string(index) + " out of range (" +
                std::to_string(h.summary.size()) + " values)");
    if (name) *name = h.summary[index].first.c_str();
    if (value) *value = h.summary[index].second;
    return FLEXMOOR_OK;
  });
}

}  // extern "C"
