// The life cycle of flexmoor.h: create, set up (logger, output, coupled bodies and points), init, step,
// finish, or run whole.
#include <cmath>
#include <string>
#include <vector>

#include "apps/capi/handle.hpp"
#include "apps/case/case_reader.hpp"

using namespace flexmoor;
using namespace flexmoor::capi;

namespace {

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
    *handle = addHandle(std::make_unique<flexmoor_simulation>());
  } catch (...) {
    return FLEXMOOR_FAILED;
  }
  return guarded(*handle, [&](flexmoor_simulation& h) { return create(read(), &h); });
}

// A run that ended (a RunOutcome or a SimulationResult): its summary kept, its exit code the
// call's, with what it said of a failure as the handle's message.
template <class Outcome>
int ended(flexmoor_simulation& h, const Outcome& out) {
  h.summary = out.summary;
  if (out.exit_code != app::kSuccess) h.error = h.diag.lines.kept();
  return out.exit_code;
}

}  // namespace

extern "C" {

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
    for (const std::string& n : h.coupled_names)
      require(n != name, std::string("flexmoor_couple: '") + name + "' is coupled already");
    std::vector<std::string> names = h.coupled_names;
    names.push_back(name);
    try {
      h.coupled_dofs = app::Coupling::dofsOf(*h.c, names);
    } catch (const std::invalid_argument& e) {
      throw BadCall(std::string("flexmoor_couple: ") + e.what());
    }
    h.coupled_names = names;
    return FLEXMOOR_OK;
  });
}

int flexmoor_coupled_dofs(flexmoor_t handle, int* count) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    require(count != nullptr, "flexmoor_coupled_dofs: a null count");
    *count = 0;
    for (int n : h.coupled_dofs) *count += n;
    return FLEXMOOR_OK;
  });
}

int flexmoor_init(flexmoor_t handle, int count, const double* x, const double* xd) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Created, "flexmoor_init");
    require(h.c != nullptr, "flexmoor_init: the case was not read (see flexmoor_create)");
    requireCount(h, count, "flexmoor_init");
    require(count == 0 || (x && xd), "flexmoor_init: null x or xd");
    // What the case's reading found (its warnings) to the logger set by now.
    for (const std::string& w : h.c->warnings) h.diag.stream << w << "\n";
    // From here a failure leaves the handle unusable but for its message and close.
    h.phase = flexmoor_simulation::Phase::Broken;
    h.bodies = std::make_unique<app::Coupling>(*h.c, h.coupled_names);
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
    require(*t == now, "flexmoor_step: t = " + std::to_string(*t) + " is not the time reached, " +
                           std::to_string(now) + " (a step starts where the last one ended)");
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

int flexmoor_finish(flexmoor_t handle) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_finish");
    h.phase = flexmoor_simulation::Phase::Finished;
    if (h.run) return ended(h, h.run->finish());
    return ended(h, h.simulation->finish());
  });
}

int flexmoor_run(flexmoor_t handle) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Created, "flexmoor_run");
    require(h.c != nullptr, "flexmoor_run: the case was not read (see flexmoor_create)");
    require(
        h.coupled_names.empty(),
        "flexmoor_run: a body or point is coupled (a run follows the case's own motions; step it "
        "with flexmoor_init and flexmoor_step instead)");
    for (const std::string& w : h.c->warnings) h.diag.stream << w << "\n";
    h.phase = flexmoor_simulation::Phase::Finished;
    if (h.output_dir) {
      app::RunOptions options;
      options.output_dir = *h.output_dir;
      options.figure = false;
      return ended(h, app::runCase(*h.c, options, h.log.stream, h.diag.stream));
    }
    app::Simulation simulation(*h.c, h.log.stream, h.diag.stream);
    return ended(h, simulation.run());
  });
}

}  // extern "C"
