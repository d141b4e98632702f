#pragma once
// A spring with a dashpot (k = 1e4 N/m, c = 3e3 N s/m) whose ends lie apart by (1.2, 0.4, -0.3) m
// once node 1 is displaced 0.2 m in x, both ends moving obliquely: a damping force that every
// component of the displacement and velocity feels, for checks of its matrices.
#include <Eigen/Dense>

#include "libstruct/element/spring_element.hpp"
#include "libstruct/material/cable_material.hpp"
#include "libstruct/model/state.hpp"

namespace flexmoor::test {

struct ObliqueDashpot {
  model::NodalField X = reference();
  element::SpringElement element{0, 1, 1e4, -1.0, material::Compression::Carry, 3e3};
  model::State state = moving();

  static model::NodalField reference() {
    model::NodalField X(3, 2);
    X.col(0) = Eigen::Vector3d(0.0, 0.0, 0.0);
    X.col(1) = Eigen::Vector3d(1.0, 0.4, -0.3);
    return X;
  }
  static model::State moving() {
    model::State state(2);
    state.displacement.col(1) = Eigen::Vector3d(0.2, 0.0, 0.0);
    state.velocity.col(0) = Eigen::Vector3d(0.1, -0.2, 0.05);
    state.velocity.col(1) = Eigen::Vector3d(0.5, 0.3, -0.4);
    return state;
  }
};

}  // namespace flexmoor::test
