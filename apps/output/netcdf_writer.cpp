#include "apps/output/netcdf_writer.hpp"

#include <algorithm>
#include <ctime>
#include <stdexcept>
#include <tuple>

#include "apps/output/finite_value.hpp"
#include "apps/output/membrane_resultants.hpp"
#include "libhydro/waves/sea.hpp"
#include "libhydro/waves/wave_spectrum.hpp"

namespace flexmoor::app {
namespace {

constexpr const char* kAxis[3] = {"_x", "_y", "_z"};
// CF auxiliary coordinates (CF 5): the record's step and load factor, and where a value sits.
constexpr const char* kNodeCoordinates = "step_number step_name load_factor node_x node_y node_z";
constexpr const char* kElementCoordinates =
    "step_number step_name load_factor element_x element_y element_z";

std::vector<int> oneBased(size_t count) {
  std::vector<int> index(count);
  for (size_t i = 0; i < count; ++i) index[i] = static_cast<int>(i) + 1;
  return index;
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string unitSystemName(UnitSystem system) {
  const UnitNames u = unitNames(system);
  return std::string(system == UnitSystem::US ? "US" : "SI") + " (" + u.length + ", " + u.mass +
         ", " + u.time + ", " + u.force + ")";
}

}  // namespace

NetcdfWriter::~NetcdfWriter() = default;

NetcdfWriter::NetcdfWriter(const std::string& path, const model::Model& model, const Case& c)
    : file_(path),
      node_count_(model.nodeCount()),
      element_count_(model.elementCount()),
      reference_(model.reference()),
      force_unit_(unitNames(c.units).force),
      resultant_unit_(unitNames(c.units).force + "/" + unitNames(c.units).length),
      mass_unit_(unitNames(c.units).mass),
      fields_(c.output),
      sea_(c.output.has(OutputField::WaveElevation) ? c.sea : nullptr) {
  if (node_count_ == 0 || element_count_ == 0)
    throw std::runtime_error(path + ": cannot write results of a model without nodes or elements");
  defineHeader(model, c);
  file_.endDefine();
  writeMesh(model);
  file_.sync();
}

void NetcdfWriter::defineHeader(const model::Model& model, const Case& c) {
  const std::string version = FLEXMOOR_VERSION;
  file_.putAttribute(NC_GLOBAL, "Conventions", "CF-1.8");
  file_.putAttribute(NC_GLOBAL, "title", c.title.empty() ? "flexmoor case " + c.name : c.title);
  file_.putAttribute(NC_GLOBAL, "source", "flexmoor " + version);
  file_.putAttribute(
      NC_GLOBAL, "history",
      utcNow() + ": flexmoor " + version + " run of " + (c.file.empty() ? c.name : c.file));
  file_.putAttribute(NC_GLOBAL, "case_name", c.name);
  file_.putAttribute(NC_GLOBAL, "unit_system", unitSystemName(c.units));
  if (c.sea_origin) {
    const SeaOrigin& sea = *c.sea_origin;
    file_.putAttribute(NC_GLOBAL, "sea_kind", sea.kind);
    file_.putAttribute(NC_GLOBAL, "sea_components", sea.components);
    if (!sea.discretisation.empty())
      file_.putAttribute(NC_GLOBAL, "sea_discretisation", sea.discretisation);
    if (sea.seed)
      file_.putAttribute(NC_GLOBAL, "sea_seed", static_cast<int>(*sea.seed));  // <= INT_MAX
    // In the case's time unit (s in both systems); absent when the sea does not repeat.
    if (sea.repeat_period > 0.0)
      file_.putAttribute(NC_GLOBAL, "sea_repeat_period", sea.repeat_period);
    if (sea.spectrum) defineSpectrum(*sea.spectrum, sea.band);
  }

  size_t element_nodes = 0;
  for (const auto& e : model.elements()) element_nodes += e->nodes().size();
  dim_node_ = file_.defineDimension("node", node_count_);
  dim_element_ = file_.defineDimension("element", element_count_);
  dim_end_ = file_.defineDimension("end", 2);
  dim_element_node_ = file_.defineDimension("element_node", element_nodes);
  // name_strlen: as long as the longest name written (without the case's steps, as long as any
  // step name may be).
  if (!c.steps.empty()) {
    name_length_ = 1;
    for (const StepSpec& step : c.steps)
      name_length_ = std::max(name_length_, step.name.size() + kLastConvergedSuffix.size());
    for (const auto& e : model.elements())
      name_length_ = std::max(name_length_, e->typeName().size());
  }
  text_count_[1] = name_length_;
  dim_name_ = file_.defineDimension("name_strlen", name_length_);
  dim_step_ = file_.defineDimension("time", NC_UNLIMITED);

  const UnitNames u = unitNames(c.units);
  node_index_ = defineIndex("node", dim_node_, "node number");
  element_index_ = defineIndex("element", dim_element_, "element number");
  for (int k = 0; k < 3; ++k) {
    const std::string axis(1, "xyz"[k]);
    node_coordinate_[k] = file_.defineVariable(
        std::string("node") + kAxis[k], NC_DOUBLE, {dim_node_},
        axis + " coordinate of the node in the reference configuration", u.length);
    element_coordinate_[k] = file_.defineVariable(
        std::string("element") + kAxis[k], NC_DOUBLE, {dim_element_},
        axis +
            " coordinate of the element's centroid (mean of its nodes) in the reference "
            "configuration",
        u.length);
  }
  element_type_ =
      file_.defineVariable("element_type", NC_CHAR, {dim_element_, dim_name_}, "element type");
  element_node_count_ = file_.defineVariable("element_node_count", NC_INT, {dim_element_},
                                             "number of nodes of the element");
  file_.putAttribute(element_node_count_, "sample_dimension", "element_node");
  element_nodes_ = file_.defineVariable(
      "element_nodes", NC_INT, {dim_element_node_},
      "nodes of each element in element order (first, interior..., last), 1-based");
  file_.putAttribute(element_nodes_, "start_index", 1);

  // The record dimension and its coordinate (CF 4.4): static steps keep the time of the state
  // they start from, so records of a static sequence share one time and are told apart by the
  // auxiliary coordinates step_number, step_name and load_factor.
  time_ = file_.defineVariable("time", NC_DOUBLE, {dim_step_},
                               "time since the start of the analysis", u.time);
  file_.putAttribute(time_, "standard_name", "time");
  file_.putAttribute(time_, "axis", "T");
  step_number_ = file_.defineVariable("step_number", NC_INT, {dim_step_},
                                      "analysis step of the case this record closes, 1-based");
  step_name_ = file_.defineVariable("step_name", NC_CHAR, {dim_step_, dim_name_},
                                    "name of the analysis step");
  for (const int text : {element_type_, step_name_})  // read as strings, not as bytes
    file_.putAttribute(text, "_Encoding", "utf-8");
  load_factor_ = file_.defineVariable("load_factor", NC_DOUBLE, {dim_step_}, "load factor", "1");

  // The fields of the case's `output: fields:`; a variable not defined keeps the id -1.
  const std::vector<int> step_node = {dim_step_, dim_node_};
  const auto nodal = [&](OutputField field, const std::string& name, const std::string& long_name,
                         const std::string& units) {
    Vector3Variable v = fields_.has(field) ? defineVector3(name, step_node, long_name, units)
                                           : Vector3Variable{name, {-1, -1, -1}};
    for (const int id : v.id)
      if (id >= 0) {
        file_.putAttribute(id, "coordinates", kNodeCoordinates);
        file_.writtenInFull(id);
      }
    return v;
  };
  displacement_ = nodal(OutputField::Displacement, "displacement", "displacement", u.length);
  position_ =
      nodal(OutputField::Position, "position", "coordinate in the current configuration", u.length);
  velocity_ = nodal(OutputField::Velocity, "velocity", "velocity", u.length + "/" + u.time);
  // An axisymmetric meridian's forces are per radian of circumference (its hoops' tensions are
  // whole forces).
  const bool meridian = std::any_of(model.elements().begin(), model.elements().end(),
                                    [](const auto& e) { return e->axisymmetric(); });
  reaction_ = nodal(OutputField::Reaction, "reaction", "support reaction (zero at free dofs)",
                    meridian ? u.force + "/rad" : u.force);
  if (fields_.has(OutputField::Tension)) {
    tension_end_ =
        file_.defineVariable("tension_end", NC_DOUBLE, {dim_step_, dim_element_, dim_end_},
                             "axial force at the first and the last node of the element", u.force);
    file_.putAttribute(tension_end_, "coordinates", kElementCoordinates);
    file_.putAttribute(tension_end_, "_FillValue", NC_FILL_DOUBLE);  // membranes and point masses
    // (tension_end keeps its fill: NC_NOFILL would drop the _FillValue that marks membranes.)
  }
  if (sea_) {
    wave_elevation_ = file_.defineVariable(
        "wave_elevation", NC_DOUBLE, {dim_step_},
        "incident wave elevation at x = y = 0 (with the sea's ramp)", u.length);
    file_.putAttribute(wave_elevation_, "standard_name", "sea_surface_elevation");
    file_.putAttribute(wave_elevation_, "coordinates", "step_number step_name load_factor");
    file_.writtenInFull(wave_elevation_);
  }
  for (const int id : {time_, step_number_, step_name_, load_factor_}) file_.writtenInFull(id);
}

void NetcdfWriter::defineSpectrum(const hydro::WaveSpectrum& s, std::pair<double, double> band) {
  file_.putAttribute(NC_GLOBAL, "sea_spectrum_band", std::vector<double>{band.first, band.second});
  if (s.isTable()) {
    file_.putAttribute(NC_GLOBAL, "sea_spectrum", "table");
    std::vector<double> omega, density;
    for (const auto& [w, S] : s.samples()) {
      omega.push_back(w);
      density.push_back(S);
    }
    file_.putAttribute(NC_GLOBAL, "sea_spectrum_omega", omega);
    file_.putAttribute(NC_GLOBAL, "sea_spectrum_density", density);
    return;
  }
  const double gamma = s.peakEnhancement();
  file_.putAttribute(NC_GLOBAL, "sea_spectrum", gamma == 1.0 ? "pierson_moskowitz" : "jonswap");
  file_.putAttribute(NC_GLOBAL, "sea_spectrum_Hs", s.significantHeight());
  file_.putAttribute(NC_GLOBAL, "sea_spectrum_Tp", 2.0 * std::acos(-1.0) / s.peakFrequency());
  file_.putAttribute(NC_GLOBAL, "sea_spectrum_gamma", gamma);
}

int NetcdfWriter::defineIndex(const std::string& name, int dimension,
                              const std::string& long_name) {
  const int id = file_.defineVariable(name, NC_INT, {dimension}, long_name + ", 1-based");
  file_.putAttribute(id, "start_index", 1);
  return id;
}

NetcdfWriter::Vector3Variable NetcdfWriter::defineVector3(const std::string& name,
                                                          const std::vector<int>& dimensions,
                                                          const std::string& long_name,
                                                          const std::string& units) {
  Vector3Variable v{name, {}};
  for (int k = 0; k < 3; ++k)
    v.id[k] = file_.defineVariable(name + kAxis[k], NC_DOUBLE, dimensions,
                                   std::string(1, "xyz"[k]) + " " + long_name, units);
  return v;
}

void NetcdfWriter::writeMesh(const model::Model& model) {
  const size_t nodes = node_count_;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> x(nodes);
    for (size_t n = 0; n < nodes; ++n) {
      x[n] = reference_(k, n);
      requireFinite(x[n], path(), [&] {
        return "node" + std::string(kAxis[k]) + "[node " + std::to_string(n) + "]";
      });
    }
    file_.put(node_coordinate_[k], {0}, {nodes}, x.data());
  }
  file_.put(node_index_, {0}, {nodes}, oneBased(nodes).data());
  const size_t elements = element_count_;
  file_.put(element_index_, {0}, {elements}, oneBased(elements).data());
  std::vector<int> counts, nodes_1based;
  model::NodalField centroid = model::NodalField::Zero(3, element_count_);
  for (int e = 0; e < element_count_; ++e) {
    const element::Element& element = model.element(e);
    putText(element_type_, e, element.typeName());
    counts.push_back(static_cast<int>(element.nodes().size()));
    for (const int n : element.nodes()) {
      nodes_1based.push_back(n + 1);
      centroid.col(e) += reference_.col(n) / static_cast<double>(element.nodes().size());
    }
  }
  for (int k = 0; k < 3; ++k) {
    std::vector<double> x(elements);
    for (size_t e = 0; e < elements; ++e) x[e] = centroid(k, e);
    file_.put(element_coordinate_[k], {0}, {elements}, x.data());
  }
  file_.put(element_node_count_, {0}, {counts.size()}, counts.data());
  file_.put(element_nodes_, {0}, {nodes_1based.size()}, nodes_1based.data());
}

// The layout of the first frame's element results: its integration points (with `tension`) and
// the membranes' resultants (with `membrane_resultant`, when it has membranes).
void NetcdfWriter::definePoints(const ResultFrame& first) {
  layout_defined_ = true;
  std::vector<int> point_element;
  for (int e = 0; e < element_count_; ++e) {
    element_points_.push_back(static_cast<int>(first.elements[e].point_tension.size()));
    point_element.insert(point_element.end(), element_points_.back(), e + 1);
  }
  const bool tensions = fields_.has(OutputField::Tension);
  const bool membranes = fields_.has(OutputField::MembraneResultant) &&
                         std::any_of(first.elements.begin(), first.elements.end(),
                                     [](const auto& r) { return !r.point_resultant.empty(); });
  if (!tensions && !membranes) return;
  file_.redefine();
  if (tensions) {
    dim_point_ = file_.defineDimension("point", point_element.size());
    element_point_count_ = file_.defineVariable("element_point_count", NC_INT, {dim_element_},
                                                "number of integration points of the element");
    file_.putAttribute(element_point_count_, "sample_dimension", "point");
    point_element_ = file_.defineVariable("point_element", NC_INT, {dim_point_},
                                          "element of the integration point, 1-based");
    tension_point_ = file_.defineVariable(
        "tension_point", NC_DOUBLE, {dim_step_, dim_point_},
        "axial force at the integration points, element by element in element order", force_unit_);
    file_.writtenInFull(tension_point_);
    file_.putAttribute(tension_point_, "coordinates",
                       "step_number step_name load_factor point_element");
  }
  if (membranes)
    for (auto [id, name, which] :
         {std::tuple(&resultant_max_, "membrane_resultant_max", "larger"),
          std::tuple(&resultant_min_, "membrane_resultant_min", "smaller")}) {
      *id = file_.defineVariable(name, NC_DOUBLE, {dim_step_, dim_element_},
                                 std::string(which) +
                                     " in-plane principal stress resultant of the membrane "
                                     "(mean over its integration points, per current length)",
                                 resultant_unit_);
      file_.putAttribute(*id, "_FillValue", NC_FILL_DOUBLE);  // elements that are not membranes
      file_.putAttribute(*id, "coordinates", kElementCoordinates);
    }
  file_.endDefine();
  if (tensions) {
    file_.put(element_point_count_, {0}, {element_points_.size()}, element_points_.data());
    file_.put(point_element_, {0}, {point_element.size()}, point_element.data());
  }
}

void NetcdfWriter::requireMatches(const ResultFrame& frame) const {
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(path() + ": cannot write step \"" + frame.step_name + "\": " + what);
  };
  if (!frame.state) fail("the frame has no state");
  if (frame.pending) fail("its element results are still to be computed (completeResults)");
  if (frame.step_name.size() > name_length_)
    fail("the step name is longer than name_strlen (" + std::to_string(name_length_) + ")");
  if (frame.state->displacement.cols() != node_count_ ||
      frame.state->velocity.cols() != node_count_ ||
      (fields_.has(OutputField::Reaction) && frame.reactions.cols() != node_count_))
    fail("its nodal fields do not have the model's " + std::to_string(node_count_) + " nodes");
  if (!fields_.needsElementResults()) return;  // the frame need not carry them
  if (static_cast<int>(frame.elements.size()) != element_count_)
    fail("it has " + std::to_string(frame.elements.size()) + " element results for " +
         std::to_string(element_count_) + " elements");
  for (size_t e = 0; e < element_points_.size(); ++e)
    if (static_cast<int>(frame.elements[e].point_tension.size()) != element_points_[e])
      fail("element " + std::to_string(e) + " reports " +
           std::to_string(frame.elements[e].point_tension.size()) +
           " integration points; the file's layout has " + std::to_string(element_points_[e]));
}

void NetcdfWriter::gatherNodal(const Vector3Variable& v, const model::NodalField& field,
                               const model::NodalField* plus) {
  if (v.id[0] < 0) return;  // not a field of the case's output
  const size_t nodes = node_count_;
  // The field is checked where it is (in cache), not in the record buffers just written
  // (reading those back cost as much as writing them); the buffers only when a value is not.
  // `plus` is the reference, checked once by writeMesh.
  const bool finite = field.allFinite();
  for (int k = 0; k < 3; ++k) {
    Eigen::Map<Eigen::RowVectorXd> values(file_.slot<double>(v.id[k], records_), nodes);
    if (plus)
      values = field.row(k) + plus->row(k);
    else
      values = field.row(k);
    if (!finite)
      requireAllFinite(values.data(), nodes, path(), [&](size_t n) {
        return v.name + kAxis[k] + "[step " + std::to_string(records_) + ", node " +
               std::to_string(n) + "]";
      });
  }
}

void NetcdfWriter::gatherTensions(const ResultFrame& frame) {
  if (tension_end_ < 0) return;  // not a field of the case's output
  const size_t elements = element_count_;
  double* ends = file_.slot<double>(tension_end_, records_);
  double* points = file_.slot<double>(tension_point_, records_);
  size_t point = 0;
  for (size_t e = 0; e < elements; ++e) {
    const element::ElementResult& r = frame.elements[e];
    const bool line = !r.point_tension.empty();  // an axial force applies to lines only
    for (int end = 0; end < 2; ++end)
      ends[2 * e + end] = line ? r.end_tension[end] : NC_FILL_DOUBLE;
    const size_t first = point;
    for (const double t : r.point_tension) points[point++] = t;
    requireAllFinite(points + first, point - first, path(), [&](size_t i) {
      return "tension_point[step " + std::to_string(records_) + ", point " +
             std::to_string(first + i) + "] (element " + std::to_string(e) + ")";
    });
  }
  requireAllFinite(ends, 2 * elements, path(), [&](size_t i) {
    return "tension_end[step " + std::to_string(records_) + ", element " + std::to_string(i / 2) +
           ", end " + std::to_string(i % 2) + "]";
  });
}

void NetcdfWriter::gatherResultants(const ResultFrame& frame) {
  if (resultant_max_ < 0) return;
  const size_t elements = element_count_;
  double* larger = file_.slot<double>(resultant_max_, records_);
  double* smaller = file_.slot<double>(resultant_min_, records_);
  for (size_t e = 0; e < elements; ++e) {
    const auto n = principalResultants(frame.elements[e]);
    larger[e] = n ? n->first : NC_FILL_DOUBLE;
    smaller[e] = n ? n->second : NC_FILL_DOUBLE;
    requireFinite(larger[e] + smaller[e], path(), [&] {
      return "membrane_resultant[step " + std::to_string(records_) + ", element " +
             std::to_string(e) + "]";
    });
  }
}

// Modes of a modes step: circular frequencies and mass-normalised shapes, per record (records of
// other steps keep the netCDF fill value there).
void NetcdfWriter::defineModes(size_t count) {
  mode_count_ = count;
  file_.redefine();
  dim_mode_ = file_.defineDimension("mode", count);
  const int mode_index = defineIndex("mode", dim_mode_, "mode number in ascending frequency");
  angular_frequency_ = file_.defineVariable("angular_frequency", NC_DOUBLE, {dim_step_, dim_mode_},
                                            "natural circular frequency of the mode", "rad/s");
  file_.putAttribute(angular_frequency_, "_FillValue", NC_FILL_DOUBLE);  // records of other steps
  // Mass-normalised (phi^T M phi = 1): a shape has the units of mass^-1/2.
  mode_shape_ = defineVector3("mode_shape", {dim_step_, dim_mode_, dim_node_},
                              "component of the mass-normalised mode shape", mass_unit_ + "^-0.5");
  for (const int id : mode_shape_.id) {
    file_.putAttribute(id, "_FillValue", NC_FILL_DOUBLE);
    file_.putAttribute(id, "coordinates", kNodeCoordinates);
  }
  file_.endDefine();
  file_.put(mode_index, {0}, {count}, oneBased(count).data());
}

void NetcdfWriter::gatherModes(const ResultFrame& frame) {
  if (frame.frequencies.empty()) return;
  double* f = file_.slot<double>(angular_frequency_, records_);
  std::copy(frame.frequencies.begin(), frame.frequencies.end(), f);
  requireAllFinite(f, mode_count_, path(),
                   [&](size_t m) { return "angular_frequency[mode " + std::to_string(m) + "]"; });
  const size_t nodes = node_count_;
  for (int k = 0; k < 3; ++k) {
    double* s = file_.slot<double>(mode_shape_.id[k], records_);
    for (size_t m = 0; m < mode_count_; ++m)
      for (size_t n = 0; n < nodes; ++n) s[m * nodes + n] = frame.mode_shapes[m](k, n);
    requireAllFinite(s, mode_count_ * nodes, path(), [&](size_t i) {
      return "mode_shape" + std::string(kAxis[k]) + "[mode " + std::to_string(i / nodes) +
             ", node " + std::to_string(i % nodes) + "]";
    });
  }
}

void NetcdfWriter::write(const ResultFrame& frame) {
  requireMatches(frame);
  // The layout first: defining variables writes out what is held.
  if (!layout_defined_ && fields_.needsElementResults()) definePoints(frame);
  if (!frame.frequencies.empty()) {
    if (dim_mode_ < 0) defineModes(frame.frequencies.size());
    if (frame.frequencies.size() != mode_count_)
      throw std::runtime_error(path() +
                               ": every modes step of a case must ask for the same number "
                               "of modes (" +
                               std::to_string(mode_count_) + ")");
  }
  const model::State& s = *frame.state;
  try {
    const auto gatherScalar = [&](int variable, const char* name, double value) {
      requireFinite(value, path(),
                    [&] { return std::string(name) + "[step " + std::to_string(records_) + "]"; });
      *file_.slot<double>(variable, records_) = value;
    };
    gatherScalar(time_, "time", s.time);
    gatherScalar(load_factor_, "load_factor", s.load_factor);
    if (sea_)
      gatherScalar(wave_elevation_, "wave_elevation",
                   sea_->elevation(Eigen::Vector3d::Zero(), s.time));
    gatherNodal(displacement_, s.displacement);
    gatherNodal(position_, s.displacement, &reference_);
    gatherNodal(velocity_, s.velocity);
    gatherNodal(reaction_, frame.reactions);
    gatherTensions(frame);
    gatherResultants(frame);
    gatherModes(frame);
    *file_.slot<int>(step_number_, records_) = frame.step_index + 1;
    char* name = file_.slot<char>(step_name_, records_);
    std::fill_n(std::copy(frame.step_name.begin(), frame.step_name.end(), name),
                name_length_ - frame.step_name.size(), '\0');
  } catch (...) {
    file_.drop();  // nothing of a refused record is written
    throw;
  }
  file_.commit();
  ++records_;
  file_.sync();
}

void NetcdfWriter::putText(int variable, size_t index, const std::string& text) {
  if (text.size() > name_length_)
    throw std::runtime_error(path() + ": \"" + text + "\" is longer than name_strlen (" +
                             std::to_string(name_length_) + ")");
  text_.assign(name_length_, '\0');
  text_.replace(0, text.size(), text);
  text_start_[0] = index;
  file_.put(variable, text_start_, text_count_, text_.data());
}

}  // namespace flexmoor::app
