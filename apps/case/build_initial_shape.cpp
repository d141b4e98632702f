// The start of the lines with `initial_shape: catenary` (read_initial_shape.cpp). flexmoor is
// total Lagrangian: a line's reference stays the straight line of its unstretched length, and its
// start is given as displacements from it. Its ends are where its supports put them (reference
// plus the prescribed displacement at load factor 1, or at t = 0 for a support with a history);
// the lower end is the anchor. Between them the line takes the elastic catenary
// (libhydro/mooring/catenary_line.hpp) in their vertical plane: submerged weight w = g (rho A -
// rho_w pi d^2 / 4) per unstretched length (the buoyancy where its section has hydro: in water),
// EA from the material's initial modulus, seabed contact when the case has `seabed:` and the
// anchor lies on the bed (the bed's height under the anchor taken as flat). A node at reference
// arc length s from the anchor goes to the catenary's point at s.
#include <algorithm>
#include <cmath>
#include <set>

#include "apps/case/case_builder.hpp"
#include "libhydro/mooring/catenary_line.hpp"

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

void startOnCatenary(CaseBuilder& b, const InitialShapeSpec& spec) {
  const model::Model& m = b.model;
  const HydroSpec& h = b.hydro;
  const auto fail = [&](const std::string& what) {
    b.diag.error(spec.line, spec.where + ": " + what);
  };
  const Eigen::Vector3d g = m.gravity();
  if (!(g.norm() > 0.0) || g.head<2>().norm() > 1e-12 * g.norm() || g.z() > 0.0) {
    fail("a catenary needs gravity along -z (got loads: gravity of " + formatNumber(g.norm()) +
         (g.norm() > 0.0 ? " not along -z" : "") + ", expected loads: gravity: {g: ...})");
    return;
  }
  const element::CableSection& section = spec.section->section;
  const int first = spec.nodes.front(), last = spec.nodes.back();
  const bool start_is_anchor = startPosition(m, first).z() <= startPosition(m, last).z();
  const int anchor_node = start_is_anchor ? first : last;
  const Eigen::Vector3d anchor = startPosition(m, anchor_node);
  const Eigen::Vector3d fairlead = startPosition(m, start_is_anchor ? last : first);
  const double tolerance = positionTolerance(b);
  bool on_bed = false;
  if (h.has_contact) {
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
    on_bed = anchor.z() <= bed_at_anchor + tolerance;
  }
  const Eigen::Vector3d span = fairlead - anchor;
  hydro::CatenaryLineInputs in;
  in.horizontal_span = span.head<2>().norm();
  in.vertical_span = span.z();
  in.unstretched_length = (m.reference().col(last) - m.reference().col(first)).norm();
  in.weight = submergedWeightPerLength(b, *spec.section);
  in.axial_stiffness = section.material->initialModulus() * section.area;
  in.seabed = on_bed;
  in.friction = spec.friction;
  in.max_strain = spec.max_strain;
  try {
    const hydro::CatenaryLine line = hydro::solveCatenary(in);
    const Eigen::Vector3d along = in.horizontal_span > 0.0
                                      ? Eigen::Vector3d(span.x(), span.y(), 0.0).normalized()
                                      : Eigen::Vector3d::UnitX();
    for (const int node : spec.nodes) {
      const double s = (m.reference().col(node) - m.reference().col(anchor_node)).norm();
      const hydro::CatenaryPoint p = line.at(s);
      const Eigen::Vector3d position = anchor + p.x * along + p.z * Eigen::Vector3d::UnitZ();
      b.model.setStartDisplacement(node, position - m.reference().col(node));
    }
  } catch (const hydro::CatenaryError& e) {
    fail(e.what());
  }
}

}  // namespace

double submergedWeightPerLength(const CaseBuilder& b, const SectionSpec& section) {
  double buoyancy = 0.0;  // mass of the displaced water per unstretched length
  if (b.hydro.has_water && section.hydro) {
    const double d = section.hydro->coefficients.diameter;
    buoyancy = b.hydro.water.density * M_PI * d * d / 4.0;
  }
  return b.model.gravity().norm() * (section.section.density * section.section.area - buoyancy);
}

void buildInitialShapes(CaseBuilder& b) {
  std::set<int> started;  // nodes of the lines started so far
  for (const InitialShapeSpec& spec : b.initial_shapes) {
    const auto shared = std::find_if(spec.nodes.begin(), spec.nodes.end(),
                                     [&](int n) { return started.count(n) > 0; });
    if (shared != spec.nodes.end()) {
      b.diag.error(spec.line, spec.where + ": the line shares node " +
                                  std::to_string(b.c.node_ids[*shared]) +
                                  " with another line's catenary start (got two starts for it, "
                                  "expected lines of their own nodes: multi-segment lines are "
                                  "not started on a catenary)");
      continue;
    }
    started.insert(spec.nodes.begin(), spec.nodes.end());
    startOnCatenary(b, spec);
  }
  if (!b.initial_shapes.empty()) b.model.setStartLoadFactor(1.0);
}

}  // namespace flexmoor::app
