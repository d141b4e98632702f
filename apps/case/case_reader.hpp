#pragma once
// Reads a YAML case file into a validated Case. Every problem of the file is collected and
// reported at once, as `FILE:LINE: what is wrong (got X, expected Y)`, in one CaseError.
//
// Schema (keys in brackets are optional; values with a physical dimension may carry a unit,
// see units.hpp, and are otherwise in the case's system):
//   name:     [word of letters, digits, '-', '_', '.'; default: the file's stem]
//   title:    [one line]
//   units:    US | SI                      US = ft, slug, s (lbf, lbf/ft^2); SI = m, kg, s (N, Pa)
//   materials: NAME: {type: linear_elastic, E, [compression]}                          Eq. 2.53
//                    {type: mooney_rivlin, C1, C2, [compression]}                        Eq. 2.54
//              compression: tension_only (default) | carry
//   sections:  NAME: {material, area, [density: 0], [quadrature: 0 = as many points as nodes]}
//   nodes:     ID: [x, y, z]               ids >= 1, unique, any order
//   lines:     - {[name], from: [x, y, z] | start_node: REF, to: [x, y, z] | end_node: REF,
//                 elements, order: 2..4 nodes per element, section}
//              equally spaced nodes; the generated ones take ids after the largest so far,
//              in order along the line
//   elements:  - {type: cable, nodes: [2..4 REF], section}
//              - {type: spring, nodes: [REF, REF], stiffness, [rest_length: reference distance],
//                 [compression: tension_only]}
//              - {type: point_mass, node: REF, mass}
//   node_sets: NAME: NODES
//   supports:  - {node: REF | nodes: NODES, fix: [x, y, z], [displacement]}
//              displacement: the fixed dofs' values in the order of fix, or the full [x, y, z];
//              reached at load factor 1
//   loads:     {[gravity: [gx, gy, gz] | {g: G} meaning (0, 0, -G)],
//              [nodal: - {node: REF | nodes: NODES, force: [fx, fy, fz]}]}
//   steps:     - relax: {[name], [load_factor], [tolerance], [damping], [initial_damping_factor],
//                        [decrement], [residual_tolerance], [max_steps], [max_iterations]}
//              - static: {[name], [load_factor], [increments], [newton: full | modified],
//                         [stiffness_update], [tolerance], [residual_tolerance],
//                         [criterion: displacement | residual | both], [max_iterations]}
//              defaults: solve::RelaxationOptions, solve::StaticOptions
//   water:     {density, depth}            gravity: |loads.gravity| (down), else standard g
//   waves:     [components] | {components, [kinematics_above_mean: wheeler | constant],
//                              [front: {start, [speed: group | phase], [ramp: 1 period]}]}
//              component: {height, period, [heading: 0], [phase: 0]}  (Miche's limit checked)
//   current:   {[profile: uniform], speed, [heading]} | {profile: power_law, speed, [heading],
//              [exponent: 7], [reference_depth: depth]} | {profile: table, table: [[z, U], ...]}
//   seabed:    {[stiffness: 3e6 Pa/m], [damping: 3e5 Pa s/m], [friction: 0],
//              [slip_speed: 0.01 m/s], [slope: [dz/dx, dz/dy]] | [grid: {x0, dx, y0, dy, z}]}
//   sections.NAME.hydro: {diameter, Cn, Ca, [Ct: 0], [CaAx: 0],
//              [tangential_drag_area: perimeter | diameter], [per_length: deformed | unstretched]}
//   bodies:    - {node: REF, type: sphere, diameter, Cd, [Ca: 0.5], [mass | weight]}
//              - {node: REF, [type: point], volume, [drag_area: 0], [Ca: 0], [mass | weight]}
//   summary:   NAME: {quantity, [node: REF], [element: ID, end: first | last], [scale: 1],
//                     [step: NAME or 1-based index; default: the last step],
//                     [at: TIME | stat: max | min | mean | std, [window: {[from], [to]}]]}
//              quantity: displacement_{x,y,z} | position_{x,y,z} | velocity_{x,y,z} | speed |
//                        reaction_{x,y,z} | reaction_magnitude | end_tension | max_tension |
//                        resultant_max | resultant_min | frequency
//              at / stat: of a dynamic step's accepted time steps (summary_series.hpp)
//
// REF, one node: an id, LINE.start, LINE.end, or LINE.middle (a line with an odd node count).
// NODES: `all`, a node set, a line's name (its nodes), a REF, or a list of these.
// Model nodes are the explicit nodes in ascending id, then the lines' generated nodes
// (Case::node_ids maps them back to ids). Element ids (summary `element:`) are 1-based in file
// order: explicit elements first, then the elements of each line in order; model element i is
// element id i + 1.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/case/case.hpp"
#include "apps/case/diagnostics.hpp"
#include "apps/case/node_table.hpp"

namespace flexmoor::app {

// Reads and validates a case file; throws CaseError listing every problem.
Case readCase(const std::string& path);

// A case file's document as read (yaml_load.hpp), its node marks kept, for a reader that sets
// values in it before the case is built (a study's members). `path` names the file in messages
// and is where the case's relative file names start.
struct CaseDocument {
  std::string path;
  YAML::Node root;
  std::optional<NodeTable> node_table;  // the nodes: read by node_table.hpp's fast path
};

// Throws CaseError when the file cannot be read as YAML.
CaseDocument loadCase(const std::string& path);

// Series quantities read against the case being built but reported in another file, to its
// Diagnostics (with `prefix` before each message): a study's collect: entries
// (readSeriesQuantity of case_builder.hpp). Each entry: its map, its path in that file
// ("collect[1]"), its name, and the keys the caller reads itself.
struct ForeignSeries {
  struct Entry {
    YAML::Node map;
    std::string path, name;
    std::vector<std::string> other_keys;
  };
  Diagnostics* diag = nullptr;
  std::string prefix;
  std::vector<Entry> entries;
  std::vector<std::optional<SummarySpec>> specs;  // filled: one per entry, nullopt when wrong
};

// Builds and validates the case of a loaded document, as readCase does the file's; reads
// `series` (when not null) against it. Throws CaseError for the case's own problems only.
Case readCase(const CaseDocument& document, ForeignSeries* series = nullptr);

// An existing file as it is, or with `.yaml` added; else the case `<name>.yaml` anywhere under
// FLEXMOOR_CASES_DIR (`name` with or without `.yaml`). Throws std::runtime_error when there is
// none, with the nearest names ("no case 'oc4-semi-surg'; did you mean 'oc4-semi-surge'?"; for a
// path, the nearest .yaml files next to it; every available name when none is near), or when
// there are several.
std::string resolveCasePath(const std::string& name_or_path);

// (name, title) of every .yaml under FLEXMOOR_CASES_DIR, sorted by name; the name is the file's
// stem, the title its `title:` key.
std::vector<std::pair<std::string, std::string>> listCases();

}  // namespace flexmoor::app
