#pragma once
// The nodal state of a model: reference coordinates X and the kinematic fields u, u', u''
// (3 x number of nodes each), plus the time and the load factor the state belongs to.
#include <Eigen/Core>

namespace flexmoor::model {

using NodalField = Eigen::Matrix3Xd;

struct State {
  NodalField displacement;
  NodalField velocity;
  NodalField acceleration;
  double time = 0.0;
  double load_factor = 0.0;

  explicit State(int node_count = 0)
      : displacement(NodalField::Zero(3, node_count)),
        velocity(NodalField::Zero(3, node_count)),
        acceleration(NodalField::Zero(3, node_count)) {}
};

}  // namespace flexmoor::model
