#pragma once
// DIR/<case>.nc: the results of a run in netCDF-4 following CF-1.8 where it applies: every
// variable has `long_name` and, when it has one, `units` in the case's unit system; coordinates
// are declared so that xarray and other CF readers attach them.
//
// Dimensions: node, element, end (2), element_node (all nodes of all elements), point (all
// integration points of the line elements; defined with the first record, whose element results
// give the layout), name_strlen, line (the case's named lines that are not segments of another,
// when it has any), mode (with the first modes step) and two record dimensions: time, the
// records of the dynamic steps, and stage, the states that close the other steps.
//
// Two kinds of record, so that `time` is strictly increasing and selects (ds.sel(time=2.5)):
//   time   a dynamic step's records: its first state (unless the time axis has a record at its
//          time already, the end of the dynamic step before it), every output_every-th
//          accepted time step and its last. Coordinate time(time) (standard_name time, axis T),
//          auxiliary coordinates step_number, step_name, load_factor.
//   stage  the state that closes a relax, static or modes step (they keep the time they start
//          from), and the last converged state of a step that did not converge (its name with
//          " (last converged)"). Coordinate stage(stage): the number of that step, 1-based (one
//          stage record a step at most, so ds.sel(stage=1) is the state closing step 1);
//          auxiliary coordinates stage_step (its name), stage_time, stage_load_factor.
// Each field is written under both: displacement_x (time, node) and stage_displacement_x
// (stage, node), and so on with the prefix stage_; the modes only under stage; wave_elevation
// only under time.
//
// Coordinates: node(node), element(element), end(end) (1 = the element's first node, 2 = its
// last, so ds.sel(end=1) is the first end), line(line) and mode(mode), 1-based numbers;
// auxiliary coordinates (the `coordinates` attribute) node_x/_y/_z (reference coordinates), and
// with lines node_line and node_arc_length, on nodal variables; element_x/_y/_z (reference
// centroids), and with lines element_line, on element variables; point_element on point
// variables; the record's step and load factor (above) on every record variable.
//
// Mesh: element_type (name), connectivity as a CF contiguous ragged array element_node_count +
// element_nodes (1-based nodes along the element), and the integration points as
// element_point_count + point_element (1-based element).
//
// Lines: line_name (line, name_strlen), line_anchor (line: a flag, 0 no anchor, 1 the anchor at
// the line's start, 2 at its end: a mooring line, `anchor:`, whose other end is its fairlead);
// node_line (node) and element_line (element), the line a node or element is on (its number in
// `line`; 0, the _FillValue, off the lines: membranes, explicit elements; a node where lines meet
// is the first line's); node_arc_length (node), the unstretched arc length along its line from
// the line's start (the anchor of a mooring line that starts there: spread_mooring,
// single_point_moor), _FillValue off the lines. A multi-segment line is one line here; its
// segments are named in the case file only.
//
// Per record, of the fields the case's `output: fields:` lists (all by default;
// apps/problem/output_fields.hpp): wave_elevation (time) at x = y = 0 when the case has a sea,
// displacement_/position_/velocity_/reaction_x/_y/_z (record, node), tension_end (record,
// element, end; _FillValue for elements without an axial force), tension_point (record, point),
// membrane_resultant_max/_min (record, element; _FillValue off membranes); angular_frequency
// (stage, mode) and mode_shape_x/_y/_z (stage, mode, node; mass^-1/2) with _FillValue off modes
// steps.
//
// A sea from a spectrum also states its target (the case's units: length, s, rad): sea_spectrum
// ("jonswap", "pierson_moskowitz" or "table"), sea_spectrum_band (omega_min, omega_max: the
// synthesised band, rad/s) and either sea_spectrum_Hs, sea_spectrum_Tp, sea_spectrum_gamma (1 for
// Pierson-Moskowitz; libhydro/waves/wave_spectrum.hpp's formula, normalised to m0 = Hs^2 / 16) or
// a table's samples sea_spectrum_omega (rad/s) and sea_spectrum_density (length^2 s/rad), linear
// between them.
//
// Each write is flushed to disk at most once a second (NetcdfFile::sync), so a run that is killed
// keeps every record but those of its last second.
// No NaN or infinity is ever written: a frame holding one is refused as a whole, and so is a time
// record not later than the one before it, or a second stage record of one step.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "apps/output/netcdf_file.hpp"
#include "apps/output/result_frame.hpp"
#include "apps/output/result_sink.hpp"
#include "apps/problem/case.hpp"

namespace flexmoor::app {

class NetcdfWriter final : public ResultSink {
 public:
  // Creates (or replaces) `path` and writes the header and the mesh of `model`; the global
  // attributes and units come from `c`. Throws std::runtime_error naming the path and the netCDF
  // error when a call fails.
  NetcdfWriter(const std::string& path, const model::Model& model, const Case& c);
  ~NetcdfWriter();

  // Appends one record (a stage record when frame.stage says so, else a time record) and syncs
  // the file (at most once a second). Throws std::runtime_error, before writing any of the
  // record, when the frame does not match the model or the point layout of the first frame, when
  // a value is NaN or infinite (naming the variable and its indices), when the step name is
  // longer than name_strlen, when a time record is not later than the last one, or when its
  // step has a stage record already.
  void write(const ResultFrame& frame) override;

  // Flushes every record written so far to disk now.
  void flush() override { file_.flush(); }
  // Element results and reactions are needed only for the fields that hold them.
  bool needsResults() const override { return fields_.needsResults(); }

  // Records written so far: time records, stage records.
  size_t records() const { return time_.count; }
  size_t stageRecords() const { return stage_.count; }
  const std::string& path() const { return file_.path(); }

  // name_strlen's longest: a case's longest step name and the suffix of a step that did not
  // converge. A file's name_strlen is what its names need (its longest step name with that
  // suffix, its element types), so that step_name does not pad every record to this length.
  static constexpr size_t kNameLength = kMaxNameLength + kLastConvergedSuffix.size();

 private:
  struct Vector3Variable {
    std::string name;  // variable names are name + "_x", "_y", "_z"
    std::array<int, 3> id{-1, -1, -1};
  };
  // The variables of one record dimension (time or stage) and how many records it has.
  struct Records {
    std::string prefix;  // of the field variables' names: "" (time) or "stage_"
    int dim = -1;
    size_t count = 0;
    // time: time(time), step_number, step_name, load_factor; stage: stage_time, stage(stage)
    // (the step number), stage_step, stage_load_factor.
    int time = -1, step_number = -1, step_name = -1, load_factor = -1;
    std::string node_coordinates, element_coordinates, point_coordinates;  // `coordinates`
    Vector3Variable displacement, position, velocity, reaction;
    int tension_end = -1, tension_point = -1;
    int resultant_max = -1, resultant_min = -1;  // when the first frame has membranes
  };
  void defineHeader(const model::Model& model, const Case& c);
  void defineLines();
  void defineRecords(Records& r, const std::string& units_time);
  // The target spectrum of a spectral sea as global attributes (see the header comment).
  void defineSpectrum(const hydro::WaveSpectrum& s, std::pair<double, double> band);
  Vector3Variable defineVector3(const std::string& name, const std::vector<int>& dimensions,
                                const std::string& long_name, const std::string& units);
  // A 1-based integer coordinate variable of `dimension` (node, element, mode).
  int defineIndex(const std::string& name, int dimension, const std::string& long_name);
  void writeMesh(const model::Model& model);
  void writeLines(const Case& c, const model::Model& model);
  void definePoints(const ResultFrame& first);
  void defineModes(size_t count);
  void gatherModes(const ResultFrame& frame);
  void requireMatches(const ResultFrame& frame) const;
  // field, or field + *plus (a position: reference + displacement), one record of v.
  void gatherNodal(const Records& r, const Vector3Variable& v, const model::NodalField& field,
                   const model::NodalField* plus = nullptr);
  void gatherTensions(const Records& r, const ResultFrame& frame);
  void gatherResultants(const Records& r, const ResultFrame& frame);
  void putText(int variable, size_t index, const std::string& text);

  NetcdfFile file_;
  int node_count_ = 0;
  int element_count_ = 0;
  model::NodalField reference_;  // for position = reference + displacement
  std::string force_unit_, resultant_unit_, mass_unit_, length_unit_, reaction_unit_;
  OutputFields fields_;              // what the records hold (the case's `output: fields:`)
  bool layout_defined_ = false;      // definePoints has run
  std::vector<int> element_points_;  // integration points per element, from the first frame
  // Buffers reused by every record, so that writing a record allocates nothing (its values go
  // straight into the file's record buffers: NetcdfFile::slot).
  std::string text_;
  size_t name_length_ = kNameLength;  // name_strlen of this file
  std::vector<size_t> text_start_{0, 0}, text_count_{1, 0};

  int dim_node_ = -1, dim_element_ = -1, dim_end_ = -1, dim_name_ = -1;
  int dim_element_node_ = -1, dim_point_ = -1, dim_line_ = -1;
  std::array<int, 3> node_coordinate_{}, element_coordinate_{};
  int seabed_z_ = -1;                   // with a seabed: its height under each node
  std::vector<double> seabed_heights_;  // written with the mesh
  int node_index_ = -1, element_index_ = -1, end_index_ = -1;
  int element_type_ = -1, element_node_count_ = -1, element_nodes_ = -1;
  int line_index_ = -1, line_name_ = -1, line_anchor_ = -1;
  int node_line_ = -1, element_line_ = -1, node_arc_length_ = -1;
  Records time_, stage_;
  std::vector<int> staged_steps_;          // the steps with a stage record, 1-based
  double last_time_ = 0.0;                 // of the last time record
  std::shared_ptr<const hydro::Sea> sea_;  // with a sea: wave_elevation
  int wave_elevation_ = -1;
  int element_point_count_ = -1, point_element_ = -1;
  int dim_mode_ = -1, angular_frequency_ = -1;  // defined with the first modes step
  size_t mode_count_ = 0;
  Vector3Variable mode_shape_;
};

}  // namespace flexmoor::app
