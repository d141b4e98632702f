#include "apps/case/scenarios/single_point_moor.hpp"

#include <cmath>
#include <memory>

#include "apps/problem/unit_system.hpp"
#include "libstruct/material/cable_material.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

const CaseLine& cableOf(const CaseSpec& c) { return c.lines.front(); }

SummarySpec buoySummary(const CaseSpec& c, const std::string& name, SummarySpec::Quantity q,
                        int component, const std::string& unit) {
  SummarySpec s;
  s.name = name;
  s.quantity = q;
  s.node = cableOf(c).nodes.back();
  s.component = component;
  s.unit = unit;
  return s;
}

}  // namespace

CaseSpec singlePointMoor(const SinglePointMoorSpec& spec, std::vector<StepSpec> steps) {
  CaseSpec c;
  c.units = spec.units;
  const double g = spec.water.gravity;
  const double d = spec.hydro.coefficients.diameter, area = kPi * d * d / 4.0;
  element::CableSection section;
  section.area = area;
  section.density = spec.weight_in_air / (g * area);  // mass per length over the area
  section.material = std::make_shared<material::LinearElasticCable>(
      spec.ea / area, material::Compression::TensionOnly);

  CaseLine cable{"cable", {}, {}, "", CaseLine::Anchor::Start};
  const Eigen::Vector3d end = spec.anchor + Eigen::Vector3d(spec.length, 0.0, 0.0);
  const int count = spec.elements * (spec.order - 1) + 1;
  for (int k = 0; k < count; ++k) {
    const double s = static_cast<double>(k) / (count - 1);
    cable.nodes.push_back(c.mesh.addNode((1.0 - s) * spec.anchor + s * end));
  }
  for (int e = 0; e < spec.elements; ++e) {
    const auto first = cable.nodes.begin() + e * (spec.order - 1);
    cable.elements.push_back(c.mesh.addElement(
        ElementSpec::cable(std::vector<int>(first, first + spec.order), section, 0)));
  }
  const int buoy = cable.nodes.back();
  if (spec.buoy_mass > 0.0) c.mesh.addElement(ElementSpec::pointMass(buoy, spec.buoy_mass));

  // The plane, the anchor, the buoy held where the spec puts it.
  for (int node = 0; node < c.mesh.nodeCount(); ++node)
    c.conditions.supports.push_back({node, 1, 0.0, nullptr, 0});
  for (const int k : {0, 2})
    c.conditions.supports.push_back({cable.nodes.front(), k, 0.0, nullptr, 0});
  c.conditions.supports.push_back({buoy, 0, spec.held_x - spec.length, nullptr, 0});
  c.conditions.supports.push_back({buoy, 2, spec.held_z, nullptr, 0});
  c.conditions.gravity = Eigen::Vector3d(0.0, 0.0, -g);

  c.ocean = OceanSpec::inWater(spec.water);
  c.ocean.morison.push_back({cable.elements, spec.hydro});
  c.ocean.bodies.push_back({buoy, spec.buoy, 0, "buoy"});
  c.lines.push_back(cable);
  c.steps = std::move(steps);
  c.summary = singlePointMoorSummary(c);
  c.figure = singlePointMoorFigure(c);
  return c;
}

StepSpec singlePointMoorHold(const SinglePointMoorSpec& spec) {
  StepSpec hold;
  hold.kind = StepSpec::Kind::Relax;
  hold.name = "held";
  hold.relax.tolerance = 1e-6;
  hold.relax.damping = 0.01 * spec.ea / spec.length;
  hold.relax.initial_damping_factor = 0.01;
  return hold;
}

StepSpec singlePointMoorRelease(int buoy) {
  StepSpec release;
  release.kind = StepSpec::Kind::Dynamic;
  release.name = "released";
  release.release = {{buoy, 0}, {buoy, 2}};
  return release;
}

std::vector<SummarySpec> singlePointMoorSummary(const CaseSpec& c) {
  using Quantity = SummarySpec::Quantity;
  const UnitNames units = unitNames(c.units);
  std::vector<SummarySpec> summary = {
      buoySummary(c, "buoy_x", Quantity::Position, 0, units.length),
      buoySummary(c, "buoy_z", Quantity::Position, 2, units.length)};
  // The extremes of a last step that is dynamic.
  if (c.steps.empty() || c.steps.back().kind != StepSpec::Kind::Dynamic) return summary;
  summary.push_back(
      buoySummary(c, "buoy_speed_max", Quantity::Speed, 0, units.length + "/" + units.time));
  summary.back().reduction = SummarySpec::Reduction::Max;
  SummarySpec tension;
  tension.name = "anchor_tension_max";
  tension.quantity = Quantity::EndTension;
  tension.element = cableOf(c).elements.front();
  tension.end = 0;
  tension.reduction = SummarySpec::Reduction::Max;
  tension.unit = units.force;
  summary.push_back(tension);
  return summary;
}

FigureSpec singlePointMoorFigure(const CaseSpec& c) {
  FigureSpec figure;
  const int buoy = cableOf(c).nodes.back();
  for (const char* q : {"position_x", "position_z", "speed"})
    figure.series.push_back(FigureSpec::nodeSeries(q, buoy));
  figure.series.push_back(FigureSpec::tensionSeries(cableOf(c).elements.front(), 0));
  return figure;
}

}  // namespace flexmoor::app
