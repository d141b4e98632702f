#pragma once
// Small ocean models built in code for the libhydro load tests: a sea of one Airy wave and a
// sheared current, and a straight line of cable elements carrying a Morison line load and, on
// request, seabed contact. The structure's cross-section is the hydrodynamic one (A = pi d^2 / 4).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "libhydro/loads/morison.hpp"
#include "libhydro/seabed/bathymetry.hpp"
#include "libhydro/seabed/seabed_contact.hpp"
#include "libhydro/waves/sea.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/model/model.hpp"

namespace flexmoor::test {

constexpr double kSeaWaterDensity = 1025.0, kStandardGravity = 9.80665;

// A 1.5 m, 8 s Airy wave heading 30 degrees (phase 0.4) at `depth`, and a 1/7 power-law current
// of 0.8 m/s at the surface heading 100 degrees.
std::shared_ptr<hydro::Sea> waveAndCurrentSea(double depth);
// Water of `depth` with nothing moving in it.
std::shared_ptr<hydro::Sea> stillWater(double depth);

struct OceanLineInputs {
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::UnitX();
  int elements = 1;
  int nodes_per_element = 2;
  double youngs_modulus = 1.0e9;
  double density = 1000.0;             // of the structure, per reference volume
  hydro::MorisonCoefficients morison;  // its diameter is the section's too
  model::LengthMeasure measure = model::LengthMeasure::Current;
  std::shared_ptr<const hydro::Sea> sea;
  std::optional<hydro::Bathymetry> bed;  // seabed contact over the width d when set
  hydro::SeabedProperties bed_properties;
};

struct OceanLine {
  std::unique_ptr<model::Model> model;  // equations not numbered: the caller constrains first
  std::vector<int> nodes;               // along the line
};

OceanLine makeOceanLine(const OceanLineInputs& inputs);

// The sum of the external load over every node.
Eigen::Vector3d totalExternalLoad(const model::Assembler& assembler, const model::State& state);

}  // namespace flexmoor::test
