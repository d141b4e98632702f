#include "apps/case/scenarios/submerged_tube.hpp"

#include <array>
#include <cmath>
#include <memory>

#include "apps/case/build/surface_mesh.hpp"
#include "apps/problem/unit_system.hpp"
#include "libstruct/material/cable_material.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

// The tube's centre and radius, and where the cables are attached and anchored.
struct TubeGeometry {
  double radius, zc, za, xa, run;
};

TubeGeometry geometryOf(const SubmergedTubeSpec& s) {
  TubeGeometry t;
  t.radius = s.diameter / 2.0;
  t.zc = -s.axis_depth;
  t.za = t.zc - t.radius * std::cos(s.attach_angle);
  t.xa = t.radius * std::sin(s.attach_angle);
  t.run = (t.za + s.water.depth) * std::tan(s.angle);
  return t;
}

// The node at a point of the tube's ring y = 0 (the mesh has one there: its corners).
int nodeAt(const MeshSpec& mesh, const Eigen::Vector3d& x) {
  const auto [nearest, distance] = mesh.nearestNode(x);
  return distance <= mesh.positionTolerance() ? nearest : -1;
}

// The top, bottom, right and left of the ring y = 0: the dissertation's nodes 1, 7, 4 and 10.
std::array<int, 4> ringNodes(const CaseSpec& c, const SubmergedTubeSpec& spec) {
  const TubeGeometry t = geometryOf(spec);
  return {nodeAt(c.mesh, {0.0, 0.0, t.zc + t.radius}), nodeAt(c.mesh, {0.0, 0.0, t.zc - t.radius}),
          nodeAt(c.mesh, {t.radius, 0.0, t.zc}), nodeAt(c.mesh, {-t.radius, 0.0, t.zc})};
}

}  // namespace

CaseSpec submergedTube(const SubmergedTubeSpec& spec, std::vector<StepSpec> steps) {
  CaseSpec c;
  c.units = spec.units;
  const TubeGeometry t = geometryOf(spec);
  const double depth = spec.water.depth, g = spec.water.gravity;

  // The cables, from their attachments at the tube down to the bed.
  std::vector<CaseLine> lines;
  for (const double side : {1.0, -1.0}) {
    CaseLine line{side > 0.0 ? "mooring_right" : "mooring_left", {}, {}, "", CaseLine::Anchor::End};
    const Eigen::Vector3d from(side * t.xa, spec.layer / 2.0, t.za);
    const Eigen::Vector3d to(side * (t.xa + t.run), spec.layer / 2.0, -depth);
    const int count = spec.elements * (spec.order - 1) + 1;
    for (int k = 0; k < count; ++k) {
      const double s = static_cast<double>(k) / (count - 1);
      line.nodes.push_back(c.mesh.addNode((1.0 - s) * from + s * to));
    }
    lines.push_back(line);
  }
  // The tube: one layer of Q8 elements, a corner at 180 deg - attach_angle (its nodes merged
  // with the cables' at their attachments).
  SectionSpec wall;
  wall.is_membrane = true;
  wall.membrane = spec.wall;
  SurfaceSpec surface;
  surface.name = "tube";
  surface.map.shape = SurfaceShape::Cylinder;
  surface.map.axis = 1;
  surface.map.origin = Eigen::Vector3d(0.0, 0.0, t.zc);
  surface.map.radius = t.radius;
  surface.map.length = spec.layer;
  surface.map.theta0 = kPi - spec.attach_angle;
  surface.map.theta1 = 3.0 * kPi - spec.attach_angle;
  surface.kind = {false, 8, 2};
  surface.divisions = {spec.around, 1};
  surface.section = &wall;
  SurfaceElements tube = meshSurface(c.mesh.reference, surface, {},
                                     [&](const Eigen::Vector3d& x) { return c.mesh.addNode(x); });
  for (CaseLine& line : lines)
    for (int e = 0; e < spec.elements; ++e) {
      const auto first = line.nodes.begin() + e * (spec.order - 1);
      line.elements.push_back(c.mesh.addElement(
          ElementSpec::cable(std::vector<int>(first, first + spec.order), spec.rope, 0)));
    }
  std::vector<int> membranes;
  for (SurfaceElements::Generated& e : tube.elements)
    membranes.push_back(c.mesh.addElement(std::move(e.element)));
  c.surfaces["tube"] = tube.nodes;
  c.element_sets["tube"] = membranes;

  // The symmetry planes, the anchors; gravity.
  for (int node = 0; node < c.mesh.nodeCount(); ++node)
    c.conditions.supports.push_back({node, 1, 0.0, nullptr, 0});
  for (const CaseLine& line : lines)
    for (const int k : {0, 2})
      c.conditions.supports.push_back({line.nodes.back(), k, 0.0, nullptr, 0});
  c.conditions.gravity = Eigen::Vector3d(0.0, 0.0, -g);

  // The water: the cables' Morison loads, the waves' pressure on the tube; the liquid inside at
  // the sea's pressure at the axis plus the resultant.
  c.ocean = OceanSpec::inWater(spec.water);
  MorisonSpec morison{{}, spec.hydro};
  for (const CaseLine& line : lines)
    morison.elements.insert(morison.elements.end(), line.elements.begin(), line.elements.end());
  c.ocean.morison.push_back(morison);
  c.ocean.wave_pressures.push_back({membranes, hydro::WaterSide::Positive, 0, "tube"});
  const double pressure = spec.resultant + spec.water.density * g * spec.axis_depth;
  c.enclosed_fluids.push_back(
      {membranes, hydro::EnclosedFluid{spec.liquid_density, pressure, t.zc, g}, 0, "liquid"});
  c.lines = lines;
  c.steps = std::move(steps);
  c.summary = submergedTubeSummary(c, spec);
  c.figure = submergedTubeFigure(c, spec);
  return c;
}

StepSpec submergedTubeEquilibrium(const SubmergedTubeSpec& spec) {
  const TubeGeometry t = geometryOf(spec);
  const double length = std::hypot(t.run, t.za + spec.water.depth);
  const double ea = spec.rope.material->initialModulus() * spec.rope.area;
  StepSpec relax;
  relax.kind = StepSpec::Kind::Relax;
  relax.name = "equilibrium";
  relax.relax.tolerance = 1e-6;
  relax.relax.damping = std::pow(10.0, std::round(std::log10(2.0 * ea / length)));
  return relax;
}

StepSpec submergedTubeModes() {
  StepSpec modes;
  modes.kind = StepSpec::Kind::Modes;
  modes.name = "modes";
  modes.modes.modes = 6;
  return modes;
}

std::vector<SummarySpec> submergedTubeSummary(const CaseSpec& c, const SubmergedTubeSpec& spec) {
  using Quantity = SummarySpec::Quantity;
  const UnitNames units = unitNames(c.units);
  std::vector<SummarySpec> summary;
  const auto add = [&](const std::string& name, Quantity q, const std::string& unit) {
    SummarySpec s;
    s.name = name;
    s.quantity = q;
    s.unit = unit;
    summary.push_back(s);
    return &summary.back();
  };
  // The periods of the step `modes`, as many as it has, up to 6 and to the tube's 3 an element.
  for (size_t i = 0; i < c.steps.size(); ++i) {
    const StepSpec& step = c.steps[i];
    if (step.kind != StepSpec::Kind::Modes || step.name != "modes") continue;
    for (int k = 1; k <= 6 && k <= 3 * spec.around && k <= step.modes.modes; ++k) {
      SummarySpec* s = add("period_" + std::to_string(k), Quantity::Period, units.time);
      s->mode = k;
      s->step = static_cast<int>(i);
    }
    break;
  }
  if (c.steps.empty() || c.steps.back().kind != StepSpec::Kind::Dynamic) return summary;
  const std::array<int, 4> ring = ringNodes(c, spec);
  SummarySpec* x1 = add("node1_x_max", Quantity::Displacement, units.length);
  x1->node = ring[0];
  x1->reduction = SummarySpec::Reduction::Max;
  SummarySpec* z7 = add("node7_z_max", Quantity::Displacement, units.length);
  z7->node = ring[1];
  z7->component = 2;
  z7->reduction = SummarySpec::Reduction::Max;
  add("mooring_tension_max", Quantity::MaxTension, units.force)->reduction =
      SummarySpec::Reduction::Max;
  return summary;
}

FigureSpec submergedTubeFigure(const CaseSpec& c, const SubmergedTubeSpec& spec) {
  FigureSpec figure;
  for (const int node : ringNodes(c, spec))
    for (const char* q : {"displacement_x", "displacement_z"})
      figure.series.push_back(FigureSpec::nodeSeries(q, node));
  figure.series.push_back(FigureSpec::tensionSeries(0, 0));  // the first cable element's
  return figure;
}

}  // namespace flexmoor::app
