#pragma once
// Support reactions of a state: F - P at the constrained dofs, zero elsewhere (inertia not
// included).
#include "libstruct/model/assembler.hpp"

namespace flexmoor::app {

model::NodalField supportReactions(const model::Assembler& assembler, const model::State& state);

}  // namespace flexmoor::app
