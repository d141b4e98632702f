#pragma once
// The line types and mooring lines of scenario: spread_mooring (spread_mooring.cpp) as
// read, and whether each can start on its catenary: parsing and the catenary check only.
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

namespace flexmoor::app {

// A line type as read: what its section and the catenary start need, and its hydro keys.
struct LineType {
  double area = 0.0, mass_per_length = 0.0, ea = 0.0, diameter = 0.0;
  YAML::Node node;  // its map in the file, for the keys copied with their place
};

struct MooringSegment {
  std::string type;
  double length = 0.0;
  int elements = 20, order = 3;
};

struct MooringAttachment {
  int at = 0;  // the connection point, 1-based
  double mass = 0.0, volume = 0.0;
  std::optional<YAML::Node> drag_area, added_mass;  // as given, for the body's keys
};

struct MooringLine {
  Eigen::Vector3d anchor, fairlead;
  bool has_segments = false;             // given with segments: (else one line type)
  std::vector<MooringSegment> segments;  // from the anchor; one when has_segments is false
  std::vector<MooringAttachment> attachments;
  double length() const;
};

std::optional<LineType> readLineType(Input& in, const MapEntry& e, double rho, double g);

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
