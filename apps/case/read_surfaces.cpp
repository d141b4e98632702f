// surfaces: generated membrane meshes (rectangle, cylinder, disc, axisymmetric meridian).
#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

void readSurfaces(CaseBuilder& b, const YAML::Node& n) {
  if (n && n.size() > 0) b.diag.error(n, "surfaces: not read yet (expected no surfaces)");
}

}  // namespace flexmoor::app
