#pragma once
// DIR/<case>.nc: the results of a run in netCDF-4 following CF-1.8 where it applies: every
// variable has `long_name` and, when it has one, `units` in the case's unit system; coordinates
// are declared so that xarray and other CF readers attach them.
//
// Dimensions: node, element, end (2), element_node (all nodes of all elements), point (all
// integration points of the line elements; defined with the first record, whose element results
// give the layout), name_strlen, mode (with the first modes step) and the record dimension time.
//
// Coordinates: time(time) (standard_name time, axis T; static steps keep the time they start
// from), node(node), element(element) and mode(mode), 1-based numbers; auxiliary coordinates
// (the `coordinates` attribute) node_x/_y/_z (reference coordinates) on nodal variables,
// element_x/_y/_z (reference centroids) on element variables, point_element on point variables,
// and step_number, step_name, load_factor on every record variable.
//
// Mesh: element_type (name), connectivity as a CF contiguous ragged array element_node_count +
// element_nodes (1-based nodes along the element), and the integration points as
// element_point_count + point_element (1-based element).
//
// Per record, of the fields the case's `output: fields:` lists (all by default;
// apps/case/output_fields.hpp): wave_elevation (time) at x = y = 0 when the case has a sea,
// displacement_/position_/velocity_/reaction_x/_y/_z (time, node), tension_end (time,
// element, end; _FillValue for elements without an axial force), tension_point (time, point),
// membrane_resultant_max/_min (time, element; _FillValue off membranes), angular_frequency (time,
// mode) and mode_shape_x/_y/_z (time, mode, node; mass^-1/2) with _FillValue off modes steps.
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
// No NaN or infinity is ever written: a frame holding one is refused as a whole.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "apps/case/case.hpp"
#include "apps/output/netcdf_file.hpp"
#include "apps/output/result_frame.hpp"
#include "apps/output/result_sink.hpp"

namespace flexmoor::app {

class NetcdfWriter final : public ResultSink {
 public:
  // Creates (or replaces) `path` and writes the header and the mesh of `model`; the global
  // attributes and units come from `c`. Throws std::runtime_error naming the path and the netCDF
  // error when a call fails.
  NetcdfWriter(const std::string& path, const model::Model& model, const Case& c);
  ~NetcdfWriter();

  // Appends one step record and syncs the file (at most once a second). Throws std::runtime_error, before writing any
  // of the record, when the frame does not match the model or the point layout of the first
  // frame, when a value is NaN or infinite (naming the variable and its indices), or when the
  // step name is longer than name_strlen.
  void write(const ResultFrame& frame) override;

  // Flushes every record written so far to disk now.
  void flush() override { file_.flush(); }
  // Element results and reactions are needed only for the fields that hold them.
  bool needsResults() const override { return fields_.needsResults(); }

  size_t records() const { return records_; }
  const std::string& path() const { return file_.path(); }

  // name_strlen's longest: a case's longest step name and the suffix of a step that did not
  // converge. A file's name_strlen is what its names need (its longest step name with that
  // suffix, its element types), so that step_name does not pad every record to this length.
  static constexpr size_t kNameLength = kMaxNameLength + kLastConvergedSuffix.size();

 private:
  struct Vector3Variable {
    std::string name;  // variable names are name + "_x", "_y", "_z"
    std::array<int, 3> id;
  };
  void defineHeader(const model::Model& model, const Case& c);
  // The target spectrum of a spectral sea as global attributes (see the header comment).
  void defineSpectrum(const hydro::WaveSpectrum& s, std::pair<double, double> band);
  Vector3Variable defineVector3(const std::string& name, const std::vector<int>& dimensions,
                                const std::string& long_name, const std::string& units);
  // A 1-based integer coordinate variable of `dimension` (node, element, mode).
  int defineIndex(const std::string& name, int dimension, const std::string& long_name);
  void writeMesh(const model::Model& model);
  void definePoints(const ResultFrame& first);
  void defineModes(size_t count);
  void gatherModes(const ResultFrame& frame);
  void requireMatches(const ResultFrame& frame) const;
  // field, or field + *plus (a position: reference + displacement), one record of v.
  void gatherNodal(const Vector3Variable& v, const model::NodalField& field,
                   const model::NodalField* plus = nullptr);
  void gatherTensions(const ResultFrame& frame);
  void gatherResultants(const ResultFrame& frame);
  void putText(int variable, size_t index, const std::string& text);

  NetcdfFile file_;
  int node_count_ = 0;
  int element_count_ = 0;
  model::NodalField reference_;  // for position = reference + displacement
  std::string force_unit_, resultant_unit_, mass_unit_;
  OutputFields fields_;              // what the records hold (the case's `output: fields:`)
  bool layout_defined_ = false;      // definePoints has run
  std::vector<int> element_points_;  // integration points per element, from the first frame
  size_t records_ = 0;
  // Buffers reused by every record, so that writing a record allocates nothing (its values go
  // straight into the file's record buffers: NetcdfFile::slot).
  std::string text_;
  size_t name_length_ = kNameLength;  // name_strlen of this file
  std::vector<size_t> text_start_{0, 0}, text_count_{1, 0};

  int dim_step_ = -1, dim_node_ = -1, dim_element_ = -1, dim_end_ = -1, dim_name_ = -1;
  int dim_element_node_ = -1, dim_point_ = -1;
  std::array<int, 3> node_coordinate_{}, element_coordinate_{};
  int node_index_ = -1, element_index_ = -1;
  int element_type_ = -1, element_node_count_ = -1, element_nodes_ = -1;
  int step_number_ = -1, step_name_ = -1, time_ = -1, load_factor_ = -1;
  std::shared_ptr<const hydro::Sea> sea_;  // with a sea: wave_elevation
  int wave_elevation_ = -1;
  Vector3Variable displacement_, position_, velocity_, reaction_;
  int tension_end_ = -1, tension_point_ = -1, element_point_count_ = -1, point_element_ = -1;
  // Principal membrane resultants per element; defined when the first frame has membranes.
  int resultant_max_ = -1, resultant_min_ = -1;
  int dim_mode_ = -1, angular_frequency_ = -1;  // defined with the first modes step
  size_t mode_count_ = 0;
  Vector3Variable mode_shape_;
};

}  // namespace flexmoor::app
