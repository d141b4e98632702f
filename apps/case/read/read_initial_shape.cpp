// A line's `initial_shape:`, where a run starts it from:
//   initial_shape: catenary
//   initial_shape: {type: catenary, friction: 0.0, max_strain: 0.1}
// friction: the seabed friction coefficient C_B of the catenary's laid part from an anchor on the
// bed (default 0: the FE model's seabed friction acts on sliding only, so a static equilibrium has
// none; a part laid between two hanging ones starts frictionless, catenary_line.hpp); max_strain:
// the largest mean strain a taut line may need before it is taken as too short for its span.
// The segments of a multi-segment line (`segment_of:`, read_mesh.cpp) start on one catenary, the
// line's: each gives initial_shape (the first segment's friction and max_strain count) or none.
#include <map>

#include "apps/case/build/build_initial_shape.hpp"
#include "apps/case/case_builder.hpp"

namespace flexmoor::app {

void readInitialShape(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                      const std::vector<int>& nodes, const SectionSpec* section,
                      const std::string& segment_of) {
  CatenaryStartSpec spec;
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
  if (!section) return;
  spec.parts = {
      {nodes, section->section, section->hydro ? section->hydro->coefficients.diameter : 0.0}};
  b.initial_shapes.push_back({std::move(spec), segment_of});
}

std::vector<CatenaryStartSpec> catenaryStarts(CaseBuilder& b) {
  std::vector<CatenaryStartSpec> starts;
  std::vector<std::string> segment_of;  // of each start
  std::map<std::string, size_t> of_name;
  for (const PendingInitialShape& shape : b.initial_shapes) {
    if (!shape.segment_of.empty())
      if (const auto it = of_name.find(shape.segment_of); it != of_name.end()) {
        starts[it->second].parts.push_back(shape.start.parts.front());
        continue;
      }
    if (!shape.segment_of.empty()) of_name.emplace(shape.segment_of, starts.size());
    starts.push_back(shape.start);
    segment_of.push_back(shape.segment_of);
  }
  std::vector<CatenaryStartSpec> complete = b.catenary_starts;
  for (size_t i = 0; i < starts.size(); ++i) {
    const std::string& name = segment_of[i];
    const int segments = name.empty() ? 1 : b.line_segments.at(name);
    const int given = static_cast<int>(starts[i].parts.size());
    if (given == segments) {
      complete.push_back(std::move(starts[i]));
      continue;
    }
    b.diag.error(starts[i].line, starts[i].where + ": " + std::to_string(given) + " of the " +
                                     std::to_string(segments) + " segments of " + name +
                                     " give initial_shape (expected all or none: the segments "
                                     "start on one catenary, the whole line's)");
  }
  return complete;
}

double submergedWeightPerLength(const CaseBuilder& b, const SectionSpec& section) {
  return submergedWeightPerLength(b.ocean, b.conditions.gravityVector().norm(), section.section,
                                  section.hydro ? section.hydro->coefficients.diameter : 0.0);
}

}  // namespace flexmoor::app
