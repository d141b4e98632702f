#include "apps/case/build/build_ocean.hpp"

#include <cmath>
#include <memory>

#include "libhydro/loads/body_node_load.hpp"
#include "libhydro/loads/morison_line_load.hpp"
#include "libhydro/loads/wave_pressure_load.hpp"
#include "libhydro/seabed/seabed_line_load.hpp"
#include "libhydro/seabed/seabed_node_load.hpp"

namespace flexmoor::app {
namespace {

const char* discretisationName(hydro::Discretisation d) {
  switch (d) {
    case hydro::Discretisation::Equal:
      return "equal";
    case hydro::Discretisation::RandomBins:
      return "random_bins";
    case hydro::Discretisation::EqualEnergy:
      return "equal_energy";
  }
  return "";
}

// The sea's components (regular, from a spectrum or from a record) and how they were made.
std::shared_ptr<const hydro::Sea> makeSea(const OceanSpec& h, SeaOrigin& origin) {
  auto sea = std::make_shared<hydro::Sea>(h.water);
  const double depth = h.water.depth, g = h.water.gravity;
  std::vector<hydro::WaveComponent> components;
  origin.kind = "regular";
  for (const WaveSpec& w : h.waves)
    components.push_back(hydro::WaveComponent::fromHeightAndPeriod(w.height, w.period, w.heading,
                                                                   w.phase, depth, g));
  if (h.spectral) {
    hydro::SynthesisedSea s =
        hydro::synthesise(h.spectral->spectrum, h.spectral->options, depth, g);
    components = std::move(s.components);
    const hydro::SynthesisOptions& o = h.spectral->options;
    const double wp = h.spectral->spectrum.peakFrequency();
    origin = {"spectrum",
              discretisationName(o.discretisation),
              o.seed,
              s.repeat_period,
              0,
              std::make_shared<const hydro::WaveSpectrum>(h.spectral->spectrum),
              {o.omega_min_ratio * wp, o.omega_max_ratio * wp}};
  }
  if (h.measured) {
    const MeasuredSeaSpec& m = *h.measured;
    hydro::ReconstructedSea s =
        hydro::reconstruct(m.record, m.heading, m.gauge, m.omega_cutoff, depth, g);
    components = std::move(s.components);
    origin = {"measured", "", std::nullopt, s.repeat_period, 0, nullptr, {0.0, 0.0}};
  }
  origin.components = static_cast<int>(components.size());
  for (const hydro::WaveComponent& c : components) sea->addComponent(c);
  if (h.front) sea->setFront(*h.front);
  if (h.ramp) sea->setRamp(*h.ramp);
  if (h.current) sea->setCurrent(*h.current);
  sea->setSurfaceKinematics(h.surface);
  return sea;
}

void addMorisonLoads(const OceanSpec& h, model::Model& m,
                     const std::shared_ptr<const hydro::Sea>& sea,
                     const std::vector<const LineHydroSpec*>& hydro) {
  const std::optional<double>& reuse = h.kinematics_reuse;
  const auto held = reuse ? std::make_shared<const hydro::HeldKinematics>(sea, *reuse) : nullptr;
  for (const model::LengthMeasure measure :
       {model::LengthMeasure::Current, model::LengthMeasure::Reference}) {
    std::vector<std::optional<hydro::MorisonCoefficients>> sections(hydro.size());
    bool any = false;
    for (size_t e = 0; e < hydro.size(); ++e)
      if (hydro[e] && hydro[e]->per_length == measure) {
        sections[e] = hydro[e]->coefficients;
        any = true;
      }
    if (!any) continue;
    auto load = std::make_shared<hydro::MorisonLineLoad>(sea, std::move(sections), measure);
    if (held) load->holdKinematics(held);
    m.addLineLoad(load);
  }
}

}  // namespace

void buildOcean(const OceanSpec& h, Case& c) {
  if (!h.has_water) return;
  model::Model& m = *c.model;
  const std::vector<const LineHydroSpec*> hydro = h.elementHydro(m.elementCount());
  SeaOrigin origin;
  const std::shared_ptr<const hydro::Sea> sea = makeSea(h, origin);
  c.sea = sea;
  c.sea_origin = origin;
  c.seabed = std::make_shared<const hydro::Bathymetry>(h.bed);
  addMorisonLoads(h, m, sea, hydro);
  for (const BodySpec& body : h.bodies)
    m.addNodeLoad(std::make_shared<hydro::BodyNodeLoad>(body.node, body.body, sea));
  for (const WavePressureSpec& w : h.wave_pressures)
    m.addSurfaceLoad(std::make_shared<hydro::IncidentPressureLoad>(sea, w.side), w.elements);
  if (!h.has_contact) return;
  // Each line element's width and node spacing (MoorDyn's segment length, over which the moordyn
  // friction law spreads a node's friction damping).
  std::vector<double> widths(hydro.size(), 0.0), node_lengths(hydro.size(), 1.0);
  for (size_t e = 0; e < hydro.size(); ++e) {
    if (!hydro[e]) continue;
    widths[e] = hydro[e]->coefficients.diameter;
    const std::vector<int>& nodes = m.element(static_cast<int>(e)).nodes();
    double length = 0.0;
    for (size_t i = 1; i < nodes.size(); ++i)
      length += (m.reference().col(nodes[i]) - m.reference().col(nodes[i - 1])).norm();
    node_lengths[e] = length / static_cast<double>(nodes.size() - 1);
  }
  c.seabed_contact = m.lineLoads().size();
  m.addLineLoad(std::make_shared<hydro::SeabedLineLoad>(h.bed, h.contact, std::move(widths),
                                                        std::move(node_lengths)));
  // Bodies touch the bed with their projected area from their lowest point: a sphere's disc
  // pi D^2 / 4 from its radius below the node; a point body as a cube of its volume, V^(2/3)
  // from half its side (a body without volume does not touch).
  for (const BodySpec& body : h.bodies) {
    const hydro::PointBody& p = body.body;
    const double side = std::cbrt(p.volume);
    const double area = p.diameter > 0.0 ? M_PI * p.diameter * p.diameter / 4.0 : side * side;
    const double offset = p.diameter > 0.0 ? 0.5 * p.diameter : 0.5 * side;
    if (area > 0.0)
      m.addNodeLoad(
          std::make_shared<hydro::SeabedNodeLoad>(body.node, h.bed, h.contact, area, offset));
  }
}

}  // namespace flexmoor::app
