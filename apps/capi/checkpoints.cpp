// The checkpoints of flexmoor.h: in memory and in files, with the host's side of the state (its
// coupled motions and its time grid).
#include <string>
#include <vector>

#include "apps/capi/handle.hpp"

using namespace flexmoor;
using namespace flexmoor::capi;

extern "C" {

int flexmoor_save(flexmoor_t handle, flexmoor_checkpoint_t* checkpoint) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requirePhase(h, flexmoor_simulation::Phase::Stepping, "flexmoor_save");
    require(checkpoint != nullptr, "flexmoor_save: a null checkpoint");
    *checkpoint = new flexmoor_checkpoint{&h,       h.simulation->save(), h.bodies->save(),
                                          h.origin, h.constant_dt,        h.steps_at_constant_dt};
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
      host.insert(host.end(),
                  {s.t, s.value, s.rate, s.acceleration, s.has_acceleration ? 1.0 : 0.0});
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
        throw std::runtime_error(std::string(path) +
                                 ": its coupled bodies and points are not this handle's");
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

}  // extern "C"
