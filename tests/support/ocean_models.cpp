#include "tests/support/ocean_models.hpp"

#include <cmath>

#include "libhydro/loads/morison_line_load.hpp"
#include "libhydro/seabed/seabed_line_load.hpp"
#include "tests/support/cable_models.hpp"

namespace flexmoor::test {

std::shared_ptr<hydro::Sea> waveAndCurrentSea(double depth) {
  auto sea = stillWater(depth);
  sea->addComponent(
      hydro::WaveComponent::fromHeightAndPeriod(1.5, 8.0, 0.5236, 0.4, depth, kStandardGravity));
  sea->setCurrent(hydro::CurrentProfile::powerLaw(0.8, 7.0, depth, 1.745));
  return sea;
}

std::shared_ptr<hydro::Sea> stillWater(double depth) {
  return std::make_shared<hydro::Sea>(hydro::Water{kSeaWaterDensity, depth, kStandardGravity});
}

OceanLine makeOceanLine(const OceanLineInputs& in) {
  OceanLine line;
  line.model = std::make_unique<model::Model>();
  model::Model& m = *line.model;
  const int first = m.addNode(in.start), last = m.addNode(in.end);
  const double d = in.morison.diameter, area = 0.25 * std::acos(-1.0) * d * d;
  line.nodes = addStraightCable(
      m, first, last, in.elements, in.nodes_per_element,
      linearElasticSection(in.youngs_modulus, area, in.density, material::Compression::Carry));
  m.addLineLoad(std::make_shared<hydro::MorisonLineLoad>(
      in.sea, std::vector<std::optional<hydro::MorisonCoefficients>>(m.elementCount(), in.morison),
      in.measure));
  if (in.bed)
    m.addLineLoad(std::make_shared<hydro::SeabedLineLoad>(
        *in.bed, in.bed_properties, std::vector<double>(m.elementCount(), d)));
  return line;
}

Eigen::Vector3d totalExternalLoad(const model::Assembler& assembler, const model::State& state) {
  Eigen::VectorXd load;
  assembler.externalLoad(state, load);
  return Eigen::Map<const Eigen::Matrix3Xd>(load.data(), 3, load.size() / 3).rowwise().sum();
}

}  // namespace flexmoor::test
