#pragma once
// Puts a case's supports and static loads (apps/problem/conditions_spec.hpp) on its model, in the
// order they were given.
#include "apps/problem/conditions_spec.hpp"
#include "libstruct/model/model.hpp"

namespace flexmoor::app {

void buildConditions(const ConditionsSpec& spec, model::Model& model);

}  // namespace flexmoor::app
