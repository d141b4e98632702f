#include "apps/case/build/build_conditions.hpp"

namespace flexmoor::app {

void buildConditions(const ConditionsSpec& spec, model::Model& model) {
  for (const SupportSpec& s : spec.supports)
    model.constrain(s.node, s.component, s.displacement, s.history);
  for (const NodalLoadSpec& l : spec.nodal_loads) model.addNodalLoad(l.node, l.force, l.history);
  for (const model::PressureLoad& p : spec.pressures) model.addPressure(p);
  if (spec.gravity) model.setGravity(*spec.gravity);
}

}  // namespace flexmoor::app
