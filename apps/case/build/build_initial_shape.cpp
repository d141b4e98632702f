// The start of the lines on their elastic catenary (catenary_start_spec.hpp). flexmoor is
// total Lagrangian: a line's reference stays the straight line of its unstretched length, and its
// start is given as displacements from it. Its ends are where its supports put them (reference
// plus the prescribed displacement at load factor 1, or at t = 0 for a support with a history);
// the lower end is the anchor. Between them the line takes the elastic catenary
// (libhydro/mooring/catenary_line.hpp) in their vertical plane: submerged weight w = g (rho A -
// rho_w pi d^2 / 4) per unstretched length (the buoyancy where it has a Morison diameter d),
// EA from the material's initial modulus, seabed contact when the case has `seabed:` and every
// part touches it (has a Morison diameter), the bed's height under the anchor taken as flat: from
// an anchor on the bed the line may lie on it up to its touchdown; from a raised anchor it may lie
// on it between the parts hanging from either end, or hang clear. A node at reference
// arc length s from the anchor goes to the catenary's point at s. The segments of a multi-segment
// line start on the line's one catenary, each segment with its own section's weight
// and EA, and at each connection node the net upward force of what is attached there: the
// buoyancy rho_w g V of its bodies (taken fully submerged) less the weight of its point masses.
#include "apps/case/build/build_initial_shape.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "apps/common/format_number.hpp"
#include "apps/problem/mesh_spec.hpp"
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
double pointForce(const OceanSpec& h, const model::Model& m, int node) {
  const double g = m.gravity().norm();
  double force = 0.0;
  if (h.has_water)
    for (const BodySpec& body : h.bodies)
      if (body.node == node) force += h.water.density * g * body.body.volume;
  for (int e = 0; e < m.elementCount(); ++e)
    if (const auto* mass = dynamic_cast<const element::PointMassElement*>(&m.element(e)))
      if (mass->nodes().front() == node) force -= g * mass->weighingMass();
  return force;
}

// One line (its parts start to end, each sharing its first node with the one before) on its
// catenary; the reason it cannot start, or "".
std::string startOnCatenary(const CatenaryStartSpec& spec, const OceanSpec& h, model::Model& m) {
  const std::vector<CatenaryPartSpec>& parts = spec.parts;
  const Eigen::Vector3d g = m.gravity();
  if (!(g.norm() > 0.0) || g.head<2>().norm() > 1e-12 * g.norm() || g.z() > 0.0)
    return "a catenary needs gravity along -z (got loads: gravity of " + formatNumber(g.norm()) +
           (g.norm() > 0.0 ? " not along -z" : "") + ", expected loads: gravity: {g: ...})";
  const int first = parts.front().nodes.front(), last = parts.back().nodes.back();
  const bool start_is_anchor = startPosition(m, first).z() <= startPosition(m, last).z();
  const Eigen::Vector3d anchor = startPosition(m, start_is_anchor ? first : last);
  const Eigen::Vector3d fairlead = startPosition(m, start_is_anchor ? last : first);
  const double tolerance = positionTolerance(m.reference());
  // Seabed contact acts on lines with a Morison diameter only (their projected width).
  const bool touches =
      h.has_contact && std::all_of(parts.begin(), parts.end(),
                                   [](const CatenaryPartSpec& p) { return p.diameter > 0.0; });
  double anchor_height = 0.0;
  if (touches) {
    const double bed_at_fairlead = h.bed.height(fairlead.x(), fairlead.y());
    const double bed_at_anchor = h.bed.height(anchor.x(), anchor.y());
    if (fairlead.z() < bed_at_fairlead - tolerance)
      return "the fairlead end is below the seabed (got z = " + formatNumber(fairlead.z()) +
             ", expected at or above the bed's " + formatNumber(bed_at_fairlead) + ")";
    if (anchor.z() < bed_at_anchor - tolerance)
      return "the anchor end is below the seabed (got z = " + formatNumber(anchor.z()) +
             ", expected at or above the bed's " + formatNumber(bed_at_anchor) + ")";
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
  for (const CatenaryPartSpec& part : parts) {
    const double length =
        (m.reference().col(part.nodes.back()) - m.reference().col(part.nodes.front())).norm();
    in.segments.push_back({length,
                           submergedWeightPerLength(h, g.norm(), part.section, part.diameter),
                           part.section.material->initialModulus() * part.section.area});
    if (offsets.size() > 1) in.connection_forces.push_back(pointForce(h, m, part.nodes.front()));
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
      for (const int node : parts[k].nodes) {
        const double along_line =
            offsets[k] +
            (m.reference().col(node) - m.reference().col(parts[k].nodes.front())).norm();
        const hydro::CatenaryPoint p = line.at(start_is_anchor ? along_line : total - along_line);
        const Eigen::Vector3d position = anchor + p.x * along + p.z * Eigen::Vector3d::UnitZ();
        m.setStartDisplacement(node, position - m.reference().col(node));
      }
  } catch (const hydro::CatenaryError& e) {
    return e.what();
  }
  return "";
}

// Why the start is not one the model can take, or "": parts with nodes of the model, each
// starting where the one before ends, and a section with a material.
std::string invalidStart(const CatenaryStartSpec& spec, const model::Model& m) {
  if (spec.parts.empty()) return "no parts (expected the line's nodes and section)";
  for (size_t k = 0; k < spec.parts.size(); ++k) {
    const CatenaryPartSpec& part = spec.parts[k];
    if (part.nodes.size() < 2) return "a part of fewer than 2 nodes";
    for (const int node : part.nodes)
      if (node < 0 || node >= m.nodeCount())
        return "node " + std::to_string(node) + " is not in the mesh (" +
               std::to_string(m.nodeCount()) + " nodes, 0-based)";
    if (!part.section.material) return "a part without a material";
    if (k > 0 && part.nodes.front() != spec.parts[k - 1].nodes.back())
      return "part " + std::to_string(k + 1) + " does not start where the one before ends";
  }
  return "";
}

}  // namespace

double submergedWeightPerLength(const OceanSpec& ocean, double g,
                                const element::CableSection& section, double diameter) {
  // The mass of the displaced water per unstretched length.
  const double buoyancy = ocean.has_water && diameter > 0.0
                              ? ocean.water.density * M_PI * diameter * diameter / 4.0
                              : 0.0;
  return g * (section.density * section.area - buoyancy);
}

std::vector<SpecError> startOnCatenaries(const std::vector<CatenaryStartSpec>& starts,
                                         const OceanSpec& ocean, Case& c) {
  model::Model& m = *c.model;
  std::vector<SpecError> errors;
  std::set<int> started;  // nodes of the lines started so far
  for (const CatenaryStartSpec& spec : starts) {
    const auto fail = [&](const std::string& what) {
      errors.push_back({spec.line, spec.where + ": " + what});
    };
    if (const std::string invalid = invalidStart(spec, m); !invalid.empty()) {
      fail(invalid);
      continue;
    }
    std::set<int> nodes;
    for (const CatenaryPartSpec& part : spec.parts)
      nodes.insert(part.nodes.begin(), part.nodes.end());
    const auto shared =
        std::find_if(nodes.begin(), nodes.end(), [&](int n) { return started.count(n) > 0; });
    if (shared != nodes.end()) {
      fail("the line shares node " + std::to_string(c.node_ids[*shared]) +
           " with another line's catenary start (got two starts for it, expected lines of their "
           "own nodes, or the segments of one line given segment_of:)");
      continue;
    }
    started.insert(nodes.begin(), nodes.end());
    if (const std::string why = startOnCatenary(spec, ocean, m); !why.empty()) fail(why);
  }
  if (!starts.empty()) m.setStartLoadFactor(1.0);
  return errors;
}

}  // namespace flexmoor::app
