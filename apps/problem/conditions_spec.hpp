#pragma once
// A case's supports and static loads as specifications: what `supports:` and `loads:` (and the
// planar models' fixed y) read into, what a program fills to state them without a case file, and
// what buildConditions (apps/case/build/build_conditions.hpp) puts on the model. Nodes are
// 0-based model nodes; values are in the case's units, reached at load factor 1 (or following
// their history in dynamic steps).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "libstruct/model/model.hpp"
#include "libstruct/model/time_function.hpp"

namespace flexmoor::app {

// One prescribed dof: its displacement times the load factor, or times history(t) when given.
struct SupportSpec {
  int node = -1;
  int component = 0;  // 0, 1, 2 = x, y, z
  double displacement = 0.0;
  std::shared_ptr<const model::TimeFunction> history;
  int line = 0;  // of the case file that states it (0: none, a planar model's y)
};

// A force on a node, times the load factor or its history.
struct NodalLoadSpec {
  int node = -1;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  std::shared_ptr<const model::TimeFunction> history;
};

struct ConditionsSpec {
  // In the order given; of two for one dof, the later holds it.
  std::vector<SupportSpec> supports;
  std::vector<NodalLoadSpec> nodal_loads;
  std::vector<model::PressureLoad> pressures;  // follower pressures on membranes (Eq. 3.30-3.37)
  std::optional<Eigen::Vector3d> gravity;      // none: no gravity

  // The support that holds the dof, or null when it is free.
  const SupportSpec* support(int node, int component) const {
    for (auto s = supports.rbegin(); s != supports.rend(); ++s)
      if (s->node == node && s->component == component) return &*s;
    return nullptr;
  }
  bool held(int node, int component) const { return support(node, component) != nullptr; }
  // Its prescribed displacement at load factor 1 (0 when free).
  double prescribed(int node, int component) const {
    const SupportSpec* s = support(node, component);
    return s ? s->displacement : 0.0;
  }
  Eigen::Vector3d gravityVector() const { return gravity.value_or(Eigen::Vector3d::Zero()); }
};

}  // namespace flexmoor::app
