// The queries of flexmoor.h: time, loads, lines, nodes, summary.
#include <algorithm>
#include <string>

#include "apps/capi/handle.hpp"

using namespace flexmoor;
using namespace flexmoor::capi;

namespace {

// Node `node` of line `line` now: its position (order 0: reference + displacement) or velocity.
int lineNodeState(flexmoor_t handle, int line, int node, double out[3], int order,
                  const char* call) {
  return guarded(handle, [&](flexmoor_simulation& h) {
    requireState(h, call);
    require(out != nullptr, std::string(call) + ": a null array");
    const int n = lineNode(h, line, node, call);
    const model::State& s = h.simulation->state();
    const Eigen::Vector3d v =
        order == 0 ? Eigen::Vector3d(h.c->model->reference().col(n) + s.displacement.col(n))
                   : Eigen::Vector3d(s.velocity.col(n));
    for (int k = 0; k < 3; ++k) out[k] = v[k];
    return FLEXMOOR_OK;
  });
}

}  // namespace

extern "C" {

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
    if (h.bodies->dofs() > 0) h.bodies->loads(h.simulation->state(), h.simulation->assembler(), f);
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
  return lineNodeState(handle, line, node, position, 0, "flexmoor_line_node_position");
}

int flexmoor_line_node_velocity(flexmoor_t handle, int line, int node, double velocity[3]) {
  return lineNodeState(handle, line, node, velocity, 1, "flexmoor_line_node_velocity");
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
