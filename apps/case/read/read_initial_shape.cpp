// A line's `initial_shape:`, where a run starts it from:
//   initial_shape: catenary
//   initial_shape: {type: catenary, friction: 0.0, max_strain: 0.1}
// friction: the seabed friction coefficient C_B of the catenary's laid part from an anchor on the
// bed (default 0: the FE model's seabed friction acts on sliding only, so a static equilibrium has
// none; a part laid between two hanging ones starts frictionless, catenary_line.hpp); max_strain:
// the largest mean strain a taut line may need before it is taken as too short for its span.
// The segments of a multi-segment line (`segment_of:`, read_mesh.cpp) start on one catenary, the
// line's: each gives initial_shape (the first segment's friction and max_strain count) or none.
#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

void readInitialShape(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                      const std::vector<int>& nodes, const SectionSpec* section,
                      const std::string& segment_of) {
  InitialShapeSpec spec;
  spec.segment_of = segment_of;
  spec.nodes = nodes;
  spec.section = section;
  spec.line = lineOf(n);
  spec.where = path;
  const std::vector<std::pair<std::string, int>> types = {{"catenary", 0}};
  if (n.IsScalar()) {
    if (!b.in.choice(n, path, types)) return;
  } else {
    Fields f(b.diag, n, path, {"type", "friction", "max_strain"});
    const YAML::Node* t = f.require("type");
    if (!f.isMap() || !t || !b.in.choice(*t, f.path("type"), types)) return;
    spec.friction = b.in.quantityOr(f, "friction", kind::kNumber, Limit::NonNegative, 0.0);
    spec.max_strain = b.in.quantityOr(f, "max_strain", kind::kNumber, Limit::Positive, 0.1);
  }
  if (section) b.initial_shapes.push_back(std::move(spec));
}

}  // namespace flexmoor::app
