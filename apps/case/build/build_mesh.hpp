#pragma once
// Puts a case's nodes and elements (apps/problem/mesh_spec.hpp) on its model, in their order, so
// that the model's node and element numbers are the specification's.
#include "apps/problem/mesh_spec.hpp"
#include "libstruct/model/model.hpp"

namespace flexmoor::app {

void buildMesh(const MeshSpec& spec, model::Model& model);

}  // namespace flexmoor::app
