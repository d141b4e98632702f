#pragma once
// The line types and mooring lines of scenario: spread_mooring (spread_mooring.hpp) as read,
// and whether each can start on its catenary: parsing and the catenary check only.
//
//   line_types: {NAME: {diameter, mass_per_length, EA, weight_in_water, ...}, ...}
//   mooring_lines:
//     - {anchor, fairlead, length, type, elements: 20, order: 3}        # one line type
//     - {anchor, fairlead,                                              # several segments
//        segments: [{type: chain, length: 100 m, elements: 6, order: 3}, {type: wire, ...}, ...],
//        attachments: [{at: 1, mass: 5000 kg, volume: 2 m^3, drag_area: 1.5 m^2, Ca: 0.5}]}
//
// Segments run from the anchor; `at: k` is the connection point between segments k and k + 1
// (1-based). An attachment is a clump weight or a buoy there: its mass (a point mass, weighing),
// its volume (buoyancy, and with drag_area and Ca the Morison loads of a point body, docs/theory.md);
// its net upward force is (rho V - m) g.
#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "apps/case/input/yaml_input.hpp"
#include "apps/problem/ocean_spec.hpp"
#include "libstruct/element/cable_element.hpp"

namespace flexmoor::app {

struct CaseBuilder;

// A line type: its section (area pi d^2 / 4, density mass_per_length / area, a linear elastic
// material of modulus EA / area, its axial damping) and its Morison coefficients.
struct LineType {
  double area = 0.0, mass_per_length = 0.0, ea = 0.0, diameter = 0.0;
  element::CableSection section;
  LineHydroSpec hydro;

  // A line type of this diameter, mass per length and EA with these Morison coefficients (their
  // diameter set to it), its law linear in the engineering strain (the mooring codes', N = EA
  // (lambda - 1)) or else Eq. 2.53's; no axial damping until section.axial_damping is set.
  static LineType of(double diameter, double mass_per_length, double ea, LineHydroSpec hydro,
                     bool engineering_strain = true,
                     material::Compression compression = material::Compression::TensionOnly);
};

struct MooringSegment {
  std::string type;
  double length = 0.0;
  int elements = 20, order = 3;
};

// A clump weight or a buoy at a connection point: a point mass of its mass, a point body of its
// volume (hydro::PointBody: drag_area is Cd times the projected area, added_mass its Ca).
struct MooringAttachment {
  int at = 0;  // the connection point, 1-based
  double mass = 0.0, volume = 0.0, drag_area = 0.0, added_mass = 0.0;
};

struct MooringLine {
  Eigen::Vector3d anchor, fairlead;
  bool has_segments = false;             // given with segments: (else one line type)
  std::vector<MooringSegment> segments;  // from the anchor; one when has_segments is false
  std::vector<MooringAttachment> attachments;
  double length() const;
};

// One entry of line_types: (its hydro and damping keys read as a section's, case_builder.hpp).
std::optional<LineType> readLineType(CaseBuilder& b, const MapEntry& e, double rho, double g);

// One item of mooring_lines: (its types checked against `types`, errors at their lines).
std::optional<MooringLine> readMooringLine(Input& in, const YAML::Node& item,
                                           const std::string& path,
                                           const std::map<std::string, LineType>& types,
                                           const YAML::Node* type_map);

// Whether the line can start: its ends in the water, above the bed, and its catenary solvable
// (the same inputs build_initial_shape.cpp gives it), reported at the line's item.
bool checkStart(Diagnostics& diag, const YAML::Node& item, const std::string& path,
                const MooringLine& line, const std::map<std::string, LineType>& types, double rho,
                double g, double depth);

}  // namespace flexmoor::app
