#pragma once
// A case's ocean as specifications, in the case's unit system: the water, its waves and current,
// the seabed and its contact, the bodies at nodes, Morison loads on cable elements and the
// incident wave pressure on membranes. The case reader fills it from `water:`, `waves:`,
// `current:`, `seabed:`, `bodies:`, the sections' `hydro:` and `loads: wave_pressure:`; a program
// fills it to state a mooring case without a case file (case_spec.hpp). buildOcean
// (apps/case/build/build_ocean.hpp) turns it into a hydro::Sea and the loads that put it on the
// model. Nodes and elements are 0-based model nodes and elements; a `line` is the case file's
// line that states the item, 0 for none.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "libhydro/loads/morison.hpp"
#include "libhydro/loads/point_body.hpp"
#include "libhydro/loads/wave_pressure_load.hpp"
#include "libhydro/seabed/bathymetry.hpp"
#include "libhydro/seabed/seabed_contact.hpp"
#include "libhydro/water/current_profile.hpp"
#include "libhydro/water/water.hpp"
#include "libhydro/waves/measured_sea.hpp"
#include "libhydro/waves/sea.hpp"
#include "libhydro/waves/time_ramp.hpp"
#include "libhydro/waves/wave_front.hpp"
#include "libhydro/waves/wave_synthesis.hpp"
#include "libstruct/model/load_point.hpp"

namespace flexmoor::app {

// A section's `hydro:`: Morison's coefficients of the lines made of it, per deformed or
// unstretched length.
struct LineHydroSpec {
  hydro::MorisonCoefficients coefficients;
  model::LengthMeasure per_length = model::LengthMeasure::Current;
  int line = 0;  // of the `hydro:` key
};

// Morison loads on these cable elements (libhydro/loads/morison_line_load.hpp), with their
// section's coefficients. The elements' diameter is also their width on the seabed.
struct MorisonSpec {
  std::vector<int> elements;
  LineHydroSpec hydro;
};

// One regular wave component of `waves:` (angles in rad).
struct WaveSpec {
  double height = 0.0, period = 0.0, heading = 0.0, phase = 0.0;
  int line = 0;
};

// `waves: {spectrum: ...}`: an irregular sea from a spectrum (angles in rad, the band in ratios
// of the peak frequency).
struct SpectralSeaSpec {
  hydro::WaveSpectrum spectrum;
  hydro::SynthesisOptions options;
  int line = 0;  // of `spectrum:`
};

// `waves: {measured: ...}`: a recorded elevation at a gauge as the sea.
struct MeasuredSeaSpec {
  hydro::ElevationRecord record;
  double heading = 0.0;
  Eigen::Vector2d gauge = Eigen::Vector2d::Zero();
  double omega_cutoff = std::numeric_limits<double>::infinity();
  int line = 0;  // of `measured:`
};

// One item of `bodies:`; its mass, if it gives one, is a point_mass element at the node.
struct BodySpec {
  int node = -1;
  hydro::PointBody body;
  int line = 0;
  std::string where;  // "bodies[2]"
};

// One item of `loads: wave_pressure:`: the incident wave pressure on these membranes.
struct WavePressureSpec {
  std::vector<int> elements;
  hydro::WaterSide side = hydro::WaterSide::Positive;
  int line = 0;
  std::string where;  // "loads.wave_pressure[0]"
};

struct OceanSpec {
  bool has_water = false;  // `water:` given: nothing else of the ocean applies without it
  int water_line = 0;
  hydro::Water water;
  std::vector<WaveSpec> waves;  // regular components
  std::optional<SpectralSeaSpec> spectral;
  std::optional<MeasuredSeaSpec> measured;
  std::optional<hydro::TimeRamp> ramp;  // `waves: ramp_up:`
  // `waves: kinematics_reuse: R`: the Morison loads hold the flow at a point over a time step's
  // iterations within R of it (held_kinematics.hpp); none: Sea::at at every call.
  std::optional<double> kinematics_reuse;
  hydro::SurfaceKinematics surface = hydro::SurfaceKinematics::Wheeler;
  std::optional<hydro::WaveFront> front;
  std::optional<hydro::CurrentProfile> current;
  // The bed lies at -depth (Bathymetry::flat(depth), as inWater sets it) unless `seabed:` gives
  // a slope or a grid; contact acts only with `seabed:` (has_contact).
  hydro::Bathymetry bed = hydro::Bathymetry::flat(0.0);
  bool has_contact = false;
  hydro::SeabedProperties contact;
  std::vector<BodySpec> bodies;
  std::vector<WavePressureSpec> wave_pressures;  // read with loads: (read_conditions.cpp)
  std::vector<MorisonSpec> morison;              // an element in one of them at most

  // The Morison coefficients of each of `elements` elements, null for none; std::out_of_range
  // for Morison loads on an element beyond them.
  std::vector<const LineHydroSpec*> elementHydro(int elements) const {
    std::vector<const LineHydroSpec*> hydro(elements, nullptr);
    for (const MorisonSpec& m : morison)
      for (const int e : m.elements) hydro.at(e) = &m.hydro;
    return hydro;
  }

  // Still water with its bed flat at -depth: the start of an ocean stated in code.
  static OceanSpec inWater(const hydro::Water& water) {
    OceanSpec spec;
    spec.has_water = true;
    spec.water = water;
    spec.bed = hydro::Bathymetry::flat(water.depth);
    return spec;
  }
};

}  // namespace flexmoor::app
