#pragma once
// The state of one case file being read, shared by the readers of its sections (read/, one file
// each: read_materials.cpp, read_mesh.cpp, read_surfaces.cpp, node_refs.cpp, read_histories.cpp,
// read_conditions.cpp, read_enclosed_fluid.cpp, read_hydro.cpp, read_steps.cpp, read_summary.cpp,
// read_output.cpp, read_figure.cpp) and by what builds and checks the model after them (build/,
// check/): the Case they fill (apps/problem/case.hpp), the specifications the model is built from
// once the file is read (apps/problem/: mesh_spec.hpp, conditions_spec.hpp, ocean_spec.hpp, the
// lines' catenary starts, the enclosed liquids), where each node and element comes from, and what
// is read before its place in them is known (the lines' cables, the surfaces' elements, the
// bodies' masses). The readers know nothing of the model.
// A name defined with errors is remembered as broken, so that what refers to it is not reported
// again.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "apps/case/check/model_checks.hpp"
#include "apps/case/input/node_table.hpp"
#include "apps/case/input/yaml_input.hpp"
#include "apps/problem/case.hpp"
#include "apps/problem/catenary_start_spec.hpp"
#include "apps/problem/conditions_spec.hpp"
#include "apps/problem/mesh_spec.hpp"
#include "apps/problem/ocean_spec.hpp"
#include "apps/problem/section_spec.hpp"
#include "libhydro/loads/enclosed_fluid.hpp"
#include "libstruct/element/cable_element.hpp"
#include "libstruct/element/membrane_element.hpp"

namespace flexmoor::app {

// What a section is asked for: cable-like elements (cables, hoop cables) or membranes.
enum class SectionUse { Cable, Membrane };

// An element one surface generates, with its element_types entry ("membrane",
// "axisymmetric_membrane", "cable", "hoop_cable") and its section's name.
struct PendingElement {
  std::string type;
  std::string section;
  ElementSpec element;
};

// The elements of one surface (read_surfaces.cpp, surface_mesh.cpp); added after the lines'
// cables and registered as the element set of the surface's name.
struct PendingSurface {
  std::string name;
  int line = 0;
  std::vector<PendingElement> elements;
};

// A cable element a line generates; added to the mesh after the explicit elements.
struct PendingCable {
  std::vector<int> nodes;
  std::string section;
  int line = 0;
  std::string where;       // "lines[2]"
  std::string name;        // the line's name, "" for none
  std::string segment_of;  // the multi-segment line it is a segment of, "" for none
};

// The mass of one item of `bodies:` (its mass: or weight:, read_hydro.cpp): a point_mass element
// at its node, added to the mesh after the ocean sections are read.
struct PendingPointMass {
  int node = -1;
  double mass = 0.0;
  int line = 0;
  std::string where;  // "bodies[2]"
};

// A line's `initial_shape: catenary` as read (read_initial_shape.cpp): one part of the line's
// catenary start, which the line's segments join once all are read (catenaryStarts).
struct PendingInitialShape {
  CatenaryStartSpec start;  // of this line alone
  std::string segment_of;   // the multi-segment line whose segment it is (read_mesh.cpp), or ""
};

// One item of `loads: enclosed_fluid:` as read (read_enclosed_fluid.cpp): the liquid in the
// membranes of `on:`; its density and gravity are resolved once the water is read, and it is put
// on the model once that is built (an EnclosedFluidSpec, build_enclosed_fluid.hpp).
struct PendingEnclosedFluid {
  std::vector<int> elements;
  std::optional<double> density, specific_gravity;  // exactly one of them
  double pressure = 0.0;
  std::optional<double> at_z;
  int line = 0;
  std::string where;                          // "loads.enclosed_fluid[0]"
  std::optional<hydro::EnclosedFluid> fluid;  // resolved; nullopt when that failed (reported)
};

struct CaseBuilder {
  CaseBuilder(Diagnostics& diag, UnitSystem units, Case& result)
      : in(diag, units), diag(diag), c(result) {}

  Input in;
  Diagnostics& diag;
  Case& c;

  std::optional<NodeTable> node_table;  // nodes: when read by the fast path (node_table.hpp)
  std::map<int, int> node_of_id;        // file id -> model node
  std::set<int> broken_node_ids;        // explicit nodes given with errors
  std::map<std::string, std::shared_ptr<const material::CableMaterial>> materials;  // null: broken
  std::map<std::string, std::optional<SectionSpec>> sections;  // nullopt: broken
  std::set<std::string> broken_node_names;  // lines and node sets defined with errors
  std::vector<PendingCable> line_cables;
  std::map<std::string, std::vector<int>> line_elements;  // the elements of each named line
  std::map<std::string, int> line_segments;  // the segment count of each multi-segment line
  std::vector<std::string> line_order;       // the named lines in the order they are defined
  std::map<std::string, CaseLine::Anchor> line_anchors;  // of the lines that say `anchor:`
  // Membrane law of each material (null: broken, or linear_elastic without nu).
  std::map<std::string, std::shared_ptr<const material::MembraneMaterial>> membrane_materials;
  std::vector<PendingSurface> surface_elements;
  std::map<std::string, std::shared_ptr<const model::TimeFunction>> histories;  // null: broken
  std::set<std::string> broken_rigid_motions;        // rigid_motion histories given with errors
  std::map<std::string, std::vector<int>> surfaces;  // nodes by name; broken: broken_node_names
  // Type of each element in file order ("cable", "spring", "point_mass", "membrane",
  // "axisymmetric_membrane", "hoop_cable"; "" when broken).
  std::vector<std::string> element_types;
  ModelOrigins origins;  // of each node and element, for the checks' messages
  MeshSpec mesh;  // nodes:, lines:, surfaces:, elements: and the bodies' masses (read_mesh.cpp)
  ConditionsSpec conditions;  // supports:, loads: and the planar models' fixed y (read_conditions)
  // The `supports:` entry that fixed each dof first (3 * node + component -> its index in
  // conditions.supports), to refuse a second one that prescribes another value.
  std::unordered_map<long long, size_t> first_support;
  bool gravity_given = false;                 // `loads: gravity` (the water takes its magnitude)
  OceanSpec ocean;                            // the ocean sections (read_hydro.cpp)
  std::vector<PendingPointMass> body_masses;  // of the bodies that give one (read_hydro.cpp)
  std::vector<PendingInitialShape> initial_shapes;    // of the lines that give one
  std::vector<CatenaryStartSpec> catenary_starts;     // of a scenario's lines
  std::vector<PendingEnclosedFluid> enclosed_fluids;  // read with loads: (read_enclosed_fluid.cpp)

  std::set<std::pair<int, int>> released;  // (node, component) freed by a step's release:
  // Adds a node with the next free id (after the largest so far).
  int addGeneratedNode(const Eigen::Vector3d& position, int line);
  int largestId() const { return node_of_id.empty() ? 0 : node_of_id.rbegin()->first; }
  // A section by name; reports an unknown one (not a broken one) and one of the other use.
  const SectionSpec* section(const YAML::Node& n, const std::string& path,
                             SectionUse use = SectionUse::Cable);
  // The name of a section read by section() ("" for nullptr).
  std::string sectionName(const SectionSpec* spec) const;
};

// "one of: a, b, c" for the keys of a map, or "a name defined first" when it is empty.
template <class Map>
std::string nameList(const Map& names) {
  if (names.empty()) return "a name defined first";
  std::string list;
  for (const auto& entry : names) list += (list.empty() ? "one of: " : ", ") + entry.first;
  return list;
}

// tension_only | carry, for materials and springs.
const std::vector<std::pair<std::string, material::Compression>>& compressionChoices();

// Section readers, in the order readCase calls them.
void readMaterials(CaseBuilder& b, const YAML::Node& n);
void readSections(CaseBuilder& b, const YAML::Node& n);
void readNodes(CaseBuilder& b, const YAML::Node& n);
void readLines(CaseBuilder& b, const YAML::Node& n);
void readSurfaces(CaseBuilder& b, const YAML::Node& n);  // read_surfaces.cpp
void readElements(CaseBuilder& b, const YAML::Node& n);  // then adds the lines' elements
void readNodeSets(CaseBuilder& b, const YAML::Node& n);
void readHistories(CaseBuilder& b, const YAML::Node& n);  // read_histories.cpp
void readSupports(CaseBuilder& b, const YAML::Node& n);
void readLoads(CaseBuilder& b, const YAML::Node& n);
// water:, waves:, current:, seabed: and bodies: of the top-level map, into b.ocean; a body's mass
// into b.body_masses. Also refuses a section's hydro: without water.
void readOcean(CaseBuilder& b, const Fields& top);
// One item of `loads: enclosed_fluid:`, and the liquids of them all resolved after readOcean:
// their density and gravity, and the element entries of their lumped masses
// (read_enclosed_fluid.cpp).
void readEnclosedFluid(CaseBuilder& b, const YAML::Node& item, const std::string& path);
void resolveEnclosedFluids(CaseBuilder& b);
// The liquids put on the built model (their pressure and lumped mass, build_enclosed_fluid.hpp)
// where their walls enclose them; the others are errors at their items (read_enclosed_fluid.cpp).
void putEnclosedFluids(CaseBuilder& b);
// The membranes of the surfaces that `on:` names (one surface or a list); nullopt when a name is
// unknown (reported) or broken (read_conditions.cpp).
std::optional<std::vector<int>> surfaceMembranes(CaseBuilder& b, const YAML::Node& on,
                                                 const std::string& path);
void readSteps(CaseBuilder& b, const YAML::Node& n);
void readSummary(CaseBuilder& b, const YAML::Node& n);
// One quantity in the form of a summary: entry, as a series over a dynamic step (its `window:`,
// else the whole step; the last step unless `step:` names another) rather than one value: no
// `at:` or `stat:`; the keys `other_keys` are the caller's to read (a study's collect:, named
// `name`, at `path`). The spec's reduction is Max, which carries the window.
std::optional<SummarySpec> readSeriesQuantity(CaseBuilder& b, const YAML::Node& n,
                                              const std::string& path, const std::string& name,
                                              const std::vector<std::string>& other_keys);
void readOutput(CaseBuilder& b, const YAML::Node& n);  // read_output.cpp
// After readOutput: a series must be of a field the records hold.
void readFigure(CaseBuilder& b, const YAML::Node& n);  // read_figure.cpp
// A line's `initial_shape:` (read_initial_shape.cpp), kept in b.initial_shapes.
void readInitialShape(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                      const std::vector<int>& nodes, const SectionSpec* section,
                      const std::string& segment_of);
// The catenary starts of a scenario's lines, then of the lines with an initial_shape:, the
// segments of a multi-segment line joined into one start, the line's; a line whose segments do
// not all give it is an error (read_initial_shape.cpp).
std::vector<CatenaryStartSpec> catenaryStarts(CaseBuilder& b);
// The weight per unstretched length of a line of this section in the case's gravity, less its
// buoyancy where the section has hydro: in water (build_initial_shape.hpp).
double submergedWeightPerLength(const CaseBuilder& b, const SectionSpec& section);
// A section's `hydro:` (read_hydro.cpp), or its keys (diameter, Cn, Ct, Ca, CaAx,
// tangential_drag_area, per_length) among the keys of `f`.
std::optional<LineHydroSpec> readLineHydro(CaseBuilder& b, const YAML::Node& n,
                                           const std::string& path);
std::optional<LineHydroSpec> readLineHydro(CaseBuilder& b, Fields& f);
// A cable section's `damping:` (BA or zeta) into `section` (read_materials.cpp).
bool readLineDamping(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                     element::CableSection& section);
// The six motions of a rigid body (surge, sway, heave, roll, pitch, yaw, each optional) and its
// `ramp:` among the keys of `f`, each ramped in (read_histories.cpp); nullopt after reporting an
// error.
std::optional<model::RigidBodyMotion::Dofs> readRigidMotions(CaseBuilder& b, Fields& f);
// A step of `kind` from the keys of `map` (null: none) over `step`'s values, named `name` unless
// it gives name: (read_steps.cpp): a scenario's own step keys.
void readStepOf(CaseBuilder& b, StepSpec step, const YAML::Node* map, const std::string& path,
                const std::string& name);

// `history: NAME` of a load or a support: the named time function (read_histories.cpp); reports
// an unknown name, returns nullptr for it and for a broken one.
std::shared_ptr<const model::TimeFunction> historyRef(CaseBuilder& b, const YAML::Node& n,
                                                      const std::string& path);

// Node references (node_refs.cpp). One node: an id, LINE.start, LINE.end or LINE.middle.
std::optional<int> nodeRef(CaseBuilder& b, const YAML::Node& n, const std::string& path);
// Several nodes: `all`, a node set, a line (all its nodes), one node reference, or a list of
// these. Duplicates are dropped, the first occurrence's order kept.
std::optional<std::vector<int>> nodeListRef(CaseBuilder& b, const YAML::Node& n,
                                            const std::string& path);
// `node: REF` or `nodes: LIST` (exactly one of them) in a map.
std::optional<std::vector<int>> nodeOrNodes(CaseBuilder& b, Fields& f);
// A list of dofs from x, y, z, each once: [x, z] -> {0, 2}.
std::optional<std::vector<int>> readFix(CaseBuilder& b, const YAML::Node& n,
                                        const std::string& path);

// Places on a named line (line_refs.cpp), for summary: entries, figure: series and a study's
// collect: entries. `line: NAME`: the named line (segments included), or nullptr after reporting
// an unknown name (a broken one silently).
const CaseLine* lineRef(CaseBuilder& b, const YAML::Node& n, const std::string& path);
// `end:` of a line: start | end | first | last | 1 | 2, and anchor | fairlead of a mooring line
// (`anchor:`): true for the line's last node, false for its first.
std::optional<bool> lineEnd(CaseBuilder& b, const CaseLine& line, const YAML::Node& n,
                            const std::string& path);
// `end:` of an element: first | 1 (its first node) -> 0, last | 2 (its last node) -> 1.
std::optional<int> elementEnd(CaseBuilder& b, const YAML::Node& n, const std::string& path);
// The node of an entry of a node quantity: `node: REF`, or `line: NAME` with `end: E` or
// `node: K` (the line's K-th node, 1-based).
std::optional<int> nodeOfEntry(CaseBuilder& b, Fields& f);
// The element end of an entry of an end quantity: `element: ID, end: E` (the element read by
// `element_id`), or `line: NAME` with `end: E` (the element at that end of the line, at its
// end there) or with `element: K, end: E` (the line's K-th element, 1-based).
struct ElementEndRef {
  int element;  // 0-based model element
  int end;      // 0: its first node, 1: its last
};
std::optional<ElementEndRef> elementEndOfEntry(
    CaseBuilder& b, Fields& f,
    const std::function<std::optional<int>(const YAML::Node&, const std::string&)>& element_id);

// Checks that a name can be used to refer to something (a word without '.', not a number).
bool checkName(CaseBuilder& b, const YAML::Node& at, const std::string& path,
               const std::string& name);

}  // namespace flexmoor::app
