// The start of the lines with `initial_shape: catenary` (read_initial_shape.cpp). flexmoor is
// total Lagrangian: a line's reference stays the straight line of its unstretched length, and its
// start is given as displacements from it. Its ends are where its supports put them (reference
// plus the prescribed displacement at load factor 1, or at t = 0 for a support with a history);
// the lower end is the anchor. Between them the line takes the elastic catenary
// (libhydro/mooring/catenary_line.hpp) in their vertical plane: submerged weight w = g (rho A -
// rho_w pi d^2 / 4) per unstretched length (the buoyancy where its section has hydro: in water),
// EA from the material's initial modulus, seabed contact when the case has `seabed:` and every
// part's section touches it (has hydro:), the bed's height under the anchor taken as flat: from
// an anchor on the bed the line may lie on it up to its touchdown; from a raised anchor it may lie
// on it between the parts hanging from either end, or hang clear. A node at reference
// arc length s from the anchor goes to the catenary's point at s. The segments of a multi-segment
// line (segment_of:) start on the line's one catenary, each segment with its own section's weight
// and EA, and at each connection node the net upward force of what is attached there: the
// buoyancy rho_w g V of its bodies (taken fully submerged) less the weight of its point masses.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "apps/case/case_builder.hpp"
#include "apps/common/format_number.hpp"
#include "libhydro/mooring/catenary_line.hpp"
#include "libstruct/element/spring_element.hpp"

namespace flexmoor::app {
namespace {

// Where a node starts: its reference, moved by its supports' prescribed displacements.
Eigen::Vector3d startPosition(const model::Model& m, int node) {
  Eigen::Vector3d p = m.reference().col(node);
  for (int k = 0; k < 3; ++k)
    if (m.isConstrained(node, k))
      p(k) += m.prescribed(node, k) * (m.motion(node, k) ? m.motion(node, k)->value(0.0) : 1.0);
  return p;
}

// The net upward point force at a node: the buoyancy rho_w g V of the bodies there (taken fully
// submerged) less the weight of the point masses there.
double pointForce(const CaseBuilder& b, int node) {
  const double g = b.model.gravity().norm();
  double force = 0.0;
  if (b.hydro.has_water)
    for (const BodySpec& body : b.hydro.bodies)
      if (body.node == node) force += b.hydro.water.density * g * body.body.volume;
  for (int e = 0; e < b.model.elementCount(); ++e)
    if (b.element_types[e] == "point_mass" && b.model.element(e).nodes().front() == node)
      force -= g * static_cast<const element::PointMassElement&>(b.model.element(e)).weighingMass();
  return force;
}

// One line, or the segments of a multi-segment line (`parts`, start to end, each sharing its
// first node with the one before), on its catenary.
void startOnCatenary(CaseBuilder& b, const std::vector<const InitialShapeSpec*>& parts) {
  const model::Model& m = b.model;
  const HydroSpec& h = b.hydro;
  const InitialShapeSpec& spec = *parts.front();
  const auto fail = [&](const std::string& what) {
    b.diag.error(spec.line, spec.where + ": " + what);
  };
  const Eigen::Vector3d g = m.gravity();
  if (!(g.norm() > 0.0) || g.head<2>().norm() > 1e-12 * g.norm() || g.z() > 0.0) {
    fail("a catenary needs gravity along -z (got loads: gravity of " + formatNumber(g.norm()) +
         (g.norm() > 0.0 ? " not along -z" : "") + ", expected loads: gravity: {g: ...})");
    return;
  }
  const int first = spec.nodes.front(), last = parts.back()->nodes.back();
  const bool start_is_anchor = startPosition(m, first).z() <= startPosition(m, last).z();
  const Eigen::Vector3d anchor = startPosition(m, start_is_anchor ? first : last);
  const Eigen::Vector3d fairlead = startPosition(m, start_is_anchor ? last : first);
  const double tolerance = positionTolerance(b);
  // Seabed contact acts on lines of sections with hydro: only (their projected width).
  const bool touches = h.has_contact && std::all_of(parts.begin(), parts.end(), [](const auto* p) {
                         return p->section->hydro.has_value();
                       });
  double anchor_height = 0.0;
  if (touches) {
    const double bed_at_fairlead = h.bed.height(fairlead.x(), fairlead.y());
    const double bed_at_anchor = h.bed.height(anchor.x(), anchor.y());
    if (fairlead.z() < bed_at_fairlead - tolerance) {
      fail("the fairlead end is below the seabed (got z = " + formatNumber(fairlead.z()) +
           ", expected at or above the bed's " + formatNumber(bed_at_fairlead) + ")");
      return;
    }
    if (anchor.z() < bed_at_anchor - tolerance) {
      fail("the anchor end is below the seabed (got z = " + formatNumber(anchor.z()) +
           ", expected at or above the bed's " + formatNumber(bed_at_anchor) + ")");
      return;
    }
    anchor_height = anchor.z() <= bed_at_anchor + tolerance ? 0.0 : anchor.z() - bed_at_anchor;
  }
  const Eigen::Vector3d span = fairlead - anchor;
  hydro::CatenaryLineInputs in;
  in.horizontal_span = span.head<2>().norm();
  in.vertical_span = span.z();
  in.seabed = touches;
  in.anchor_height = anchor_height;
  in.friction = spec.friction;
  in.max_strain = spec.max_strain;
  // Each part's segment, from the start; the arc length where each part starts.
  std::vector<double> offsets = {0.0};
  for (const InitialShapeSpec* part : parts) {
    const element::CableSection& section = part->section->section;
    const double length =
        (m.reference().col(part->nodes.back()) - m.reference().col(part->nodes.front())).norm();
    in.segments.push_back({length, submergedWeightPerLength(b, *part->section),
                           section.material->initialModulus() * section.area});
    if (offsets.size() > 1) in.connection_forces.push_back(pointForce(b, part->nodes.front()));
    offsets.push_back(offsets.back() + length);
  }
  const double total = offsets.back();
  if (!start_is_anchor) {
    std::reverse(in.segments.begin(), in.segments.end());
    std::reverse(in.connection_forces.begin(), in.connection_forces.end());
  }
  try {
    const hydro::CatenaryLine line = hydro::solveCatenary(in);
    const Eigen::Vector3d along = in.horizontal_span > 0.0
                                      ? Eigen::Vector3d(span.x(), span.y(), 0.0).normalized()
                                      : Eigen::Vector3d::UnitX();
    for (size_t k = 0; k < parts.size(); ++k)
      for (const int node : parts[k]->nodes) {
        const double along_line =
            offsets[k] +
            (m.reference().col(node) - m.reference().col(parts[k]->nodes.front())).norm();
        const hydro::CatenaryPoint p = line.at(start_is_anchor ? along_line : total - along_line);
        const Eigen::Vector3d position = anchor + p.x * along + p.z * Eigen::Vector3d::UnitZ();
        b.model.setStartDisplacement(node, position - m.reference().col(node));
      }
  } catch (const hydro::CatenaryError& e) {
    fail(e.what());
  }
}

// The lines to start: each line with an initial_shape alone, the segments of a multi-segment line
// together (in file order), refusing one whose segments do not all give it.
std::vector<std::vector<const InitialShapeSpec*>> startLines(CaseBuilder& b) {
  std::vector<std::vector<const InitialShapeSpec*>> lines;
  std::map<std::string, size_t> of_name;
  for (const InitialShapeSpec& spec : b.initial_shapes) {
    if (spec.segment_of.empty()) {
      lines.push_back({&spec});
      continue;
    }
    const auto [it, added] = of_name.emplace(spec.segment_of, lines.size());
    if (added) lines.emplace_back();
    lines[it->second].push_back(&spec);
  }
  std::vector<std::vector<const InitialShapeSpec*>> complete;
  for (auto& parts : lines) {
    const std::string& name = parts.front()->segment_of;
    const int segments = name.empty() ? 1 : b.line_segments.at(name);
    if (static_cast<int>(parts.size()) == segments) {
      complete.push_back(std::move(parts));
      continue;
    }
    b.diag.error(parts.front()->line,
                 parts.front()->where + ": " + std::to_string(parts.size()) + " of the " +
                     std::to_string(segments) + " segments of " + name +
                     " give initial_shape (expected all or none: the segments start on one "
                     "catenary, the whole line's)");
  }
  return complete;
}

}  // namespace

double submergedWeightPerLength(const CaseBuilder& b, const SectionSpec& section) {
  double buoyancy = 0.0;  // mass of the displaced water per unstretched length
  if (b.hydro.has_water && section.hydro) {
    const double d = section.hydro->coefficients.diameter;
    buoyancy = b.hydro.water.density * M_PI * d * d / 4.0;
  }
  return b.conditions.gravityVector().norm() *
         (section.section.density * section.section.area - buoyancy);
}

void buildInitialShapes(CaseBuilder& b) {
  std::set<int> started;  // nodes of the lines started so far
  for (const auto& parts : startLines(b)) {
    std::set<int> nodes;
    for (const InitialShapeSpec* part : parts) nodes.insert(part->nodes.begin(), part->nodes.end());
    const auto shared =
        std::find_if(nodes.begin(), nodes.end(), [&](int n) { return started.count(n) > 0; });
    if (shared != nodes.end()) {
      b.diag.error(parts.front()->line,
                   parts.front()->where + ": the line shares node " +
                       std::to_string(b.c.node_ids[*shared]) +
                       " with another line's catenary start (got two starts for it, expected "
                       "lines of their own nodes, or the segments of one line given "
                       "segment_of:)");
      continue;
    }
    started.insert(nodes.begin(), nodes.end());
    startOnCatenary(b, parts);
  }
  if (!b.initial_shapes.empty()) b.model.setStartLoadFactor(1.0);
}

}  // namespace flexmoor::app
