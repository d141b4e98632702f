#pragma once
// A case as read from its YAML file: the model it builds, the analysis steps to run in order, and
// the summary quantities it declares. Everything is in the case's consistent unit system.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/case/output_fields.hpp"
#include "libstruct/model/model.hpp"
#include "libstruct/model/rigid_body_motion.hpp"
#include "libstruct/solve/modal.hpp"
#include "libstruct/solve/solver_options.hpp"

namespace flexmoor::hydro {
class Bathymetry;
class Sea;
class WaveSpectrum;
}  // namespace flexmoor::hydro

namespace flexmoor::app {

// A consistent unit system: US = ft, slug, s, lbf; SI = m, kg, s, N.
enum class UnitSystem { SI, US };

struct UnitNames {
  std::string length, mass, time, force, pressure;
};
UnitNames unitNames(
    UnitSystem system);  // {"ft","slug","s","lbf","lbf/ft^2"} or {"m","kg","s","N","Pa"}

struct SourceLocation {
  std::string file;
  int line = 0;  // 1-based
};

struct StepSpec {
  enum class Kind { Relax, Static, Modes, Dynamic };
  Kind kind = Kind::Static;
  std::string name;  // "relax", "static", "modes", "dynamic", or the step's own `name:`
  solve::RelaxationOptions relax;
  solve::StaticOptions statics;
  solve::ModalOptions modes;
  solve::DynamicOptions dynamic;
  int output_every = 1;  // dynamic, fixed steps: write every N-th accepted time step (and the last)
  // Dynamic, adaptive steps: write a record every output_interval of the step's time (interpolated
  // between the steps around it) and its last state.
  double output_interval = 0.0;
  // Supports let go at the start of the step (node, component): a held buoy released. They stay
  // free in the steps after.
  std::vector<std::pair<int, int>> release;
  SourceLocation where;

  bool adaptive() const { return kind == Kind::Dynamic && dynamic.adaptive.has_value(); }
  // A dynamic step's time: its duration, or the sum of its schedule's dt x steps; 0 for the other
  // kinds.
  double duration() const {
    if (adaptive()) return dynamic.adaptive->duration;
    double t = 0.0;
    if (kind == Kind::Dynamic)
      for (const solve::TimeSegment& segment : dynamic.schedule) t += segment.dt * segment.steps;
    return t;
  }
  // The records a dynamic step streams: every output_every-th of its time steps (about: the last
  // one is always written), or one every output_interval; 0 for the other kinds.
  long streamedRecords() const {
    if (adaptive()) return std::lround(duration() / output_interval);
    long steps = 0;
    if (kind == Kind::Dynamic)
      for (const solve::TimeSegment& segment : dynamic.schedule) steps += segment.steps;
    return steps / std::max(1, output_every);
  }
};

// A scalar the case promises in summary.json.
struct SummarySpec {
  enum class Quantity {
    Displacement,        // component of a node's displacement
    Position,            // component of a node's current position
    Velocity,            // component of a node's velocity u'
    Speed,               // |u'| at a node
    Reaction,            // component of a support reaction
    ReactionMagnitude,   // |reaction| at a node
    ReactionHorizontal,  // |(reaction_x, reaction_y)| at a node
    LengthOnSeabed,      // length of a line whose weight the seabed carries (evaluateSummary)
    EndTension,          // force on one end point of an element (its nodal force balance)
    MaxTension,          // largest end tension over all elements
    Frequency,           // omega of mode `mode` (1-based) of a modes step, rad/s
    Period,              // 2 pi / omega of that mode, s
    ResultantMax,        // larger principal membrane stress resultant, mean over the element's
                         // integration points (force per current length)
    ResultantMin,        // smaller principal resultant, likewise
    CpuSeconds,          // the process's CPU time (user + system) when the summary is taken, s
  };
  // How the quantity is taken over its step: from the state that closes it, or, in a dynamic
  // step, from the series of its accepted time steps (summary_series.hpp): at a time, or a
  // statistic over the window [from, to].
  enum class Reduction { StepEnd, AtTime, Max, Min, Mean, Std };
  std::string name;
  Quantity quantity = Quantity::Displacement;
  int node = -1;                   // 0-based model node
  int element = -1;                // 0-based model element
  int end = 0;                     // 0 = first node of the element, 1 = last
  int component = 0;               // 0, 1, 2 = x, y, z
  int mode = 0;                    // Frequency: 1-based mode number
  std::vector<int> elements;       // LengthOnSeabed: the line's elements
  double weight_per_length = 0.0;  // LengthOnSeabed: the submerged weight per unstretched length
                                   // of its element at the anchor
  std::vector<double> element_weights;  // LengthOnSeabed: that of each of its elements
  double scale = 1.0;                   // e.g. -1 to report a sag as positive
  int step = -1;                        // 0-based step index; -1 = the last step
  Reduction reduction = Reduction::StepEnd;
  double at = 0.0;  // AtTime: the time, in the run's time (every dynamic step advances it)
  double from = -std::numeric_limits<double>::infinity();  // the window of a statistic; the
  double to = std::numeric_limits<double>::infinity();     // default is the whole step
  std::string unit;  // unit name in the case's system ("ft", "lbf")
  SourceLocation where;
};

// `figure:` the PNG a run draws of its time series (flexmoor plot): one panel a series, each in
// the plot's VARIABLE@INDEX form with the model's 1-based node and element numbers.
struct FigureSpec {
  // Series: the time series `series`, one panel each; Mooring: the fairlead tension of every
  // line that has an anchor over time and the lines' profiles in their vertical planes over the
  // seabed and under the water line (a spread mooring's figure when the case gives none).
  enum class Kind { Series, Mooring };
  Kind kind = Kind::Series;
  std::vector<std::string> series;
  std::string title;  // empty: the case's title
  SourceLocation where;
};

// A named line of the case (`lines:`, a multi-segment line and its segments), start to end.
struct CaseLine {
  // A mooring line's anchor end (its fairlead is the other end): `anchor: start | end`.
  enum class Anchor { None, Start, End };
  std::string name;
  std::vector<int> nodes;     // 0-based model nodes, start to end
  std::vector<int> elements;  // 0-based model elements, start to end
  std::string segment_of;     // the multi-segment line it is a segment of, "" for none
  Anchor anchor = Anchor::None;
};

// How the sea's components were made (build_hydro.cpp), for the results' metadata (the netCDF
// global attributes sea_kind, sea_components, sea_discretisation, sea_seed, sea_repeat_period and
// a spectrum's sea_spectrum_*, netcdf_writer.hpp).
struct SeaOrigin {
  std::string kind;              // "regular", "spectrum" or "measured"
  std::string discretisation;    // a spectrum's: "equal", "random_bins" or "equal_energy"
  std::optional<uint64_t> seed;  // a spectrum's
  double repeat_period = 0.0;    // the equal grid's or the record's period; 0: no repeat
  int components = 0;
  std::shared_ptr<const hydro::WaveSpectrum> spectrum;  // the target of a spectrum's sea
  std::pair<double, double> band{0.0, 0.0};  // its synthesised band [omega_min, omega_max], rad/s
};

// The longest step name a case may give: the results' netCDF holds names in fixed rows of
// this many characters (name_strlen, netcdf_writer.hpp).
inline constexpr size_t kMaxNameLength = 128;

struct Case {
  std::string name;   // `name:` in the file, or the file's stem
  std::string title;  // optional one-line description
  std::string file;   // path it was read from
  UnitSystem units = UnitSystem::SI;
  std::unique_ptr<model::Model> model;  // equations already numbered
  std::vector<StepSpec> steps;
  std::vector<SummarySpec> summary;
  std::optional<FigureSpec> figure;
  OutputFields output = OutputFields::all();          // `output: fields:`: what the records hold
  std::map<std::string, std::vector<int>> node_sets;  // named sets, 0-based nodes
  std::vector<int> node_ids;  // the file's id of each model node (explicit or generated)
  std::map<std::string, std::vector<int>> lines;  // nodes of each named line, start to end
  std::vector<CaseLine> named_lines;  // every named line in the file's order (segments included)
  std::map<std::string, std::vector<int>> element_sets;  // named groups (surfaces, lines), 0-based
  // The water (`water:`, with its waves and current) whose loads act on the model; null for none.
  std::shared_ptr<const hydro::Sea> sea;
  std::optional<SeaOrigin> sea_origin;  // with the sea
  std::shared_ptr<const hydro::Bathymetry> seabed;  // the bed under the water; null for none
  // The rigid bodies in prescribed motion by name (`histories:` of type rigid_motion, a spread
  // mooring's `platform`): the points they carry follow them, and a host program may drive them
  // (RigidBodyMotion::drive).
  std::map<std::string, std::shared_ptr<model::RigidBodyMotion>> rigid_motions;
  // "FILE:LINE: warning: ..." for what runs but perhaps not as meant (the command prints them).
  std::vector<std::string> warnings;
  // "FILE:LINE: note: ..." for the defaults a run chose that the case does not state (a motion's
  // ramp); the run prints them.
  std::vector<std::string> notes;
};

}  // namespace flexmoor::app
