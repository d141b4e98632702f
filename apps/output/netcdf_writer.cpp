#include "apps/output/netcdf_writer.hpp"

#include <algorithm>
#include <ctime>
#include <stdexcept>
#include <tuple>

#include "apps/common/format_number.hpp"
#include "apps/output/finite_value.hpp"
#include "apps/output/membrane_resultants.hpp"
#include "apps/problem/unit_system.hpp"
#include "libhydro/seabed/bathymetry.hpp"
#include "libhydro/waves/sea.hpp"

namespace flexmoor::app {
namespace {

constexpr const char* kAxis[3] = {"_x", "_y", "_z"};

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
      length_unit_(unitNames(c.units).length),
      fields_(c.output),
      sea_(c.output.has(OutputField::WaveElevation) ? c.sea : nullptr) {
  if (node_count_ == 0 || element_count_ == 0)
    throw std::runtime_error(path + ": cannot write results of a model without nodes or elements");
  defineHeader(model, c);
  file_.endDefine();
  writeMesh(model);
  writeLines(c, model);
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
  std::vector<const CaseLine*> lines;  // the whole lines, not the segments
  for (const CaseLine& l : c.named_lines)
    if (l.segment_of.empty()) lines.push_back(&l);
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
  for (const CaseLine* l : lines) name_length_ = std::max(name_length_, l->name.size());
  text_count_[1] = name_length_;
  dim_name_ = file_.defineDimension("name_strlen", name_length_);
  if (!lines.empty()) dim_line_ = file_.defineDimension("line", lines.size());
  time_.dim = file_.defineDimension("time", NC_UNLIMITED);
  stage_.dim = file_.defineDimension("stage", NC_UNLIMITED);

  const UnitNames u = unitNames(c.units);
  node_index_ = defineIndex("node", dim_node_, "node number");
  element_index_ = defineIndex("element", dim_element_, "element number");
  end_index_ = file_.defineVariable("end", NC_INT, {dim_end_},
                                    "end of the element: 1 = its first node, 2 = its last node");
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
  if (c.seabed) {  // the bed under each node, for figures of lines over it
    seabed_z_ = file_.defineVariable(
        "seabed_z", NC_DOUBLE, {dim_node_},
        "height of the seabed under the node's reference position", u.length);
    seabed_heights_.resize(node_count_);
    for (int n = 0; n < static_cast<int>(node_count_); ++n)
      seabed_heights_[n] = c.seabed->height(reference_(0, n), reference_(1, n));
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

  if (dim_line_ >= 0) defineLines();

  // The record dimensions, their coordinates and the fields under each (see the header).
  const bool meridian = std::any_of(model.elements().begin(), model.elements().end(),
                                    [](const auto& e) { return e->axisymmetric(); });
  // An axisymmetric meridian's forces are per radian of circumference (its hoops' tensions are
  // whole forces).
  reaction_unit_ = meridian ? u.force + "/rad" : u.force;
  time_.prefix = "";
  stage_.prefix = "stage_";
  const std::string node_place = dim_line_ >= 0 ? " node_line node_arc_length" : "";
  const std::string element_place = dim_line_ >= 0 ? " element_line" : "";
  time_.time = file_.defineVariable("time", NC_DOUBLE, {time_.dim},
                                    "time since the start of the analysis", u.time);
  file_.putAttribute(time_.time, "standard_name", "time");
  file_.putAttribute(time_.time, "axis", "T");
  time_.step_number = file_.defineVariable("step_number", NC_INT, {time_.dim},
                                           "analysis step the record belongs to, 1-based");
  time_.step_name = file_.defineVariable("step_name", NC_CHAR, {time_.dim, dim_name_},
                                         "name of the analysis step");
  time_.load_factor =
      file_.defineVariable("load_factor", NC_DOUBLE, {time_.dim}, "load factor", "1");
  const std::string time_place = "step_number step_name load_factor";
  stage_.step_number = file_.defineVariable(
      "stage", NC_INT, {stage_.dim},
      "analysis step whose closing state (or last converged state) the record is, 1-based");
  file_.putAttribute(stage_.step_number, "start_index", 1);
  stage_.step_name = file_.defineVariable("stage_step", NC_CHAR, {stage_.dim, dim_name_},
                                          "name of the analysis step");
  stage_.time = file_.defineVariable("stage_time", NC_DOUBLE, {stage_.dim},
                                     "time since the start of the analysis", u.time);
  stage_.load_factor =
      file_.defineVariable("stage_load_factor", NC_DOUBLE, {stage_.dim}, "load factor", "1");
  const std::string stage_place = "stage_step stage_time stage_load_factor";
  for (auto [r, place] : {std::pair{&time_, time_place}, std::pair{&stage_, stage_place}}) {
    r->node_coordinates = place + " node_x node_y node_z" + node_place;
    r->element_coordinates = place + " element_x element_y element_z" + element_place;
    r->point_coordinates = place + " point_element";
    file_.putAttribute(r->step_name, "_Encoding", "utf-8");  // read as strings, not as bytes
    defineRecords(*r, u.time);
  }
  file_.putAttribute(element_type_, "_Encoding", "utf-8");
  if (sea_) {
    wave_elevation_ = file_.defineVariable(
        "wave_elevation", NC_DOUBLE, {time_.dim},
        "incident wave elevation at x = y = 0 (with the sea's ramp)", u.length);
    file_.putAttribute(wave_elevation_, "standard_name", "sea_surface_elevation");
    file_.putAttribute(wave_elevation_, "coordinates", time_place);
    file_.writtenInFull(wave_elevation_);
  }
}

// The field variables of one record dimension (the case's `output: fields:`); a variable not
// defined keeps the id -1.
void NetcdfWriter::defineRecords(Records& r, const std::string& units_time) {
  for (const int id : {r.time, r.step_number, r.step_name, r.load_factor}) file_.writtenInFull(id);
  const std::vector<int> record_node = {r.dim, dim_node_};
  const auto nodal = [&](OutputField field, const std::string& name, const std::string& long_name,
                         const std::string& units) {
    Vector3Variable v = fields_.has(field)
                            ? defineVector3(r.prefix + name, record_node, long_name, units)
                            : Vector3Variable{r.prefix + name, {-1, -1, -1}};
    for (const int id : v.id)
      if (id >= 0) {
        file_.putAttribute(id, "coordinates", r.node_coordinates);
        file_.writtenInFull(id);
      }
    return v;
  };
  r.displacement = nodal(OutputField::Displacement, "displacement", "displacement", length_unit_);
  r.position = nodal(OutputField::Position, "position", "coordinate in the current configuration",
                     length_unit_);
  r.velocity =
      nodal(OutputField::Velocity, "velocity", "velocity", length_unit_ + "/" + units_time);
  r.reaction = nodal(OutputField::Reaction, "reaction", "support reaction (zero at free dofs)",
                     reaction_unit_);
  if (fields_.has(OutputField::Tension)) {
    r.tension_end = file_.defineVariable(
        r.prefix + "tension_end", NC_DOUBLE, {r.dim, dim_element_, dim_end_},
        "axial force at the first and the last node of the element", force_unit_);
    file_.putAttribute(r.tension_end, "coordinates", r.element_coordinates);
    file_.putAttribute(r.tension_end, "_FillValue", NC_FILL_DOUBLE);  // membranes, point masses
    // (tension_end keeps its fill: NC_NOFILL would drop the _FillValue that marks membranes.)
  }
}

// The case's lines (whole lines, in the file's order): names, anchors, and each node's and
// element's line with the nodes' unstretched arc length (see the header comment).
void NetcdfWriter::defineLines() {
  line_index_ = defineIndex("line", dim_line_, "line number");
  line_name_ =
      file_.defineVariable("line_name", NC_CHAR, {dim_line_, dim_name_}, "name of the line");
  file_.putAttribute(line_name_, "_Encoding", "utf-8");
  line_anchor_ = file_.defineVariable(
      "line_anchor", NC_INT, {dim_line_},
      "end of the line that is its anchor (a mooring line; its fairlead is the other end)");
  file_.putAttribute(line_anchor_, "flag_values", std::vector<int>{0, 1, 2});
  file_.putAttribute(line_anchor_, "flag_meanings", "no_anchor anchor_at_start anchor_at_end");
  file_.putAttribute(line_anchor_, "coordinates", "line_name");
  for (auto [id, name, what, dim] :
       {std::tuple(&node_line_, "node_line", "node", dim_node_),
        std::tuple(&element_line_, "element_line", "element", dim_element_)}) {
    *id = file_.defineVariable(
        name, NC_INT, {dim},
        std::string("line the ") + what + " is on (its number in line; 0 where it is on no line)");
    file_.putAttribute(*id, "_FillValue", 0);
    file_.putAttribute(*id, "start_index", 1);
  }
  node_arc_length_ = file_.defineVariable(
      "node_arc_length", NC_DOUBLE, {dim_node_},
      "unstretched arc length along the node's line from the line's start", length_unit_);
  file_.putAttribute(node_arc_length_, "_FillValue", NC_FILL_DOUBLE);  // nodes on no line
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
  if (seabed_z_ >= 0) file_.put(seabed_z_, {0}, {nodes}, seabed_heights_.data());
  file_.put(node_index_, {0}, {nodes}, oneBased(nodes).data());
  file_.put(end_index_, {0}, {2}, oneBased(2).data());
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

void NetcdfWriter::writeLines(const Case& c, const model::Model& model) {
  if (dim_line_ < 0) return;
  std::vector<int> node_line(node_count_, 0), element_line(element_count_, 0), anchors;
  std::vector<double> arc(node_count_, NC_FILL_DOUBLE);
  size_t number = 0;
  for (const CaseLine& l : c.named_lines) {
    if (!l.segment_of.empty()) continue;
    putText(line_name_, number, l.name);
    anchors.push_back(l.anchor == CaseLine::Anchor::Start ? 1
                      : l.anchor == CaseLine::Anchor::End ? 2
                                                          : 0);
    ++number;
    double s = 0.0;  // along the reference (the unstretched line), node to node
    for (size_t k = 0; k < l.nodes.size(); ++k) {
      const int n = l.nodes[k];
      if (k > 0) s += (model.reference().col(n) - model.reference().col(l.nodes[k - 1])).norm();
      if (node_line[n] != 0) continue;  // where lines meet: the first line's
      node_line[n] = static_cast<int>(number);
      arc[n] = s;
    }
    for (const int e : l.elements)
      if (element_line[e] == 0) element_line[e] = static_cast<int>(number);
  }
  file_.put(line_index_, {0}, {number}, oneBased(number).data());
  file_.put(line_anchor_, {0}, {number}, anchors.data());
  file_.put(node_line_, {0}, {node_line.size()}, node_line.data());
  file_.put(element_line_, {0}, {element_line.size()}, element_line.data());
  file_.put(node_arc_length_, {0}, {arc.size()}, arc.data());
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
  }
  for (Records* r : {&time_, &stage_}) {
    if (tensions) {
      r->tension_point = file_.defineVariable(
          r->prefix + "tension_point", NC_DOUBLE, {r->dim, dim_point_},
          "axial force at the integration points, element by element in element order",
          force_unit_);
      file_.writtenInFull(r->tension_point);
      file_.putAttribute(r->tension_point, "coordinates", r->point_coordinates);
    }
    if (membranes)
      for (auto [id, name, which] :
           {std::tuple(&r->resultant_max, "membrane_resultant_max", "larger"),
            std::tuple(&r->resultant_min, "membrane_resultant_min", "smaller")}) {
        *id = file_.defineVariable(r->prefix + name, NC_DOUBLE, {r->dim, dim_element_},
                                   std::string(which) +
                                       " in-plane principal stress resultant of the membrane "
                                       "(mean over its integration points, per current length)",
                                   resultant_unit_);
        file_.putAttribute(*id, "_FillValue", NC_FILL_DOUBLE);  // elements that are not membranes
        file_.putAttribute(*id, "coordinates", r->element_coordinates);
      }
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

void NetcdfWriter::gatherNodal(const Records& r, const Vector3Variable& v,
                               const model::NodalField& field, const model::NodalField* plus) {
  if (v.id[0] < 0) return;  // not a field of the case's output
  const size_t nodes = node_count_;
  // The field is checked where it is (in cache), not in the record buffers just written
  // (reading those back cost as much as writing them); the buffers only when a value is not.
  // `plus` is the reference, checked once by writeMesh.
  const bool finite = field.allFinite();
  for (int k = 0; k < 3; ++k) {
    Eigen::Map<Eigen::RowVectorXd> values(file_.slot<double>(v.id[k], r.count), nodes);
    if (plus)
      values = field.row(k) + plus->row(k);
    else
      values = field.row(k);
    if (!finite)
      requireAllFinite(values.data(), nodes, path(), [&](size_t n) {
        return v.name + kAxis[k] + "[record " + std::to_string(r.count) + ", node " +
               std::to_string(n) + "]";
      });
  }
}

void NetcdfWriter::gatherTensions(const Records& r, const ResultFrame& frame) {
  if (r.tension_end < 0) return;  // not a field of the case's output
  const size_t elements = element_count_;
  double* ends = file_.slot<double>(r.tension_end, r.count);
  double* points = file_.slot<double>(r.tension_point, r.count);
  size_t point = 0;
  for (size_t e = 0; e < elements; ++e) {
    const element::ElementResult& result = frame.elements[e];
    const bool line = !result.point_tension.empty();  // an axial force applies to lines only
    for (int end = 0; end < 2; ++end)
      ends[2 * e + end] = line ? result.end_tension[end] : NC_FILL_DOUBLE;
    const size_t first = point;
    for (const double t : result.point_tension) points[point++] = t;
    requireAllFinite(points + first, point - first, path(), [&](size_t i) {
      return r.prefix + "tension_point[record " + std::to_string(r.count) + ", point " +
             std::to_string(first + i) + "] (element " + std::to_string(e) + ")";
    });
  }
  requireAllFinite(ends, 2 * elements, path(), [&](size_t i) {
    return r.prefix + "tension_end[record " + std::to_string(r.count) + ", element " +
           std::to_string(i / 2) + ", end " + std::to_string(i % 2) + "]";
  });
}

void NetcdfWriter::gatherResultants(const Records& r, const ResultFrame& frame) {
  if (r.resultant_max < 0) return;
  const size_t elements = element_count_;
  double* larger = file_.slot<double>(r.resultant_max, r.count);
  double* smaller = file_.slot<double>(r.resultant_min, r.count);
  for (size_t e = 0; e < elements; ++e) {
    const auto n = principalResultants(frame.elements[e]);
    larger[e] = n ? n->first : NC_FILL_DOUBLE;
    smaller[e] = n ? n->second : NC_FILL_DOUBLE;
    requireFinite(larger[e] + smaller[e], path(), [&] {
      return r.prefix + "membrane_resultant[record " + std::to_string(r.count) + ", element " +
             std::to_string(e) + "]";
    });
  }
}

// Modes of a modes step: circular frequencies and mass-normalised shapes, per stage record
// (records of other steps keep the netCDF fill value there).
void NetcdfWriter::defineModes(size_t count) {
  mode_count_ = count;
  file_.redefine();
  dim_mode_ = file_.defineDimension("mode", count);
  const int mode_index = defineIndex("mode", dim_mode_, "mode number in ascending frequency");
  angular_frequency_ = file_.defineVariable("angular_frequency", NC_DOUBLE, {stage_.dim, dim_mode_},
                                            "natural circular frequency of the mode", "rad/s");
  file_.putAttribute(angular_frequency_, "_FillValue", NC_FILL_DOUBLE);  // records of other steps
  file_.putAttribute(angular_frequency_, "coordinates", "stage_step stage_time stage_load_factor");
  // Mass-normalised (phi^T M phi = 1): a shape has the units of mass^-1/2.
  mode_shape_ = defineVector3("mode_shape", {stage_.dim, dim_mode_, dim_node_},
                              "component of the mass-normalised mode shape", mass_unit_ + "^-0.5");
  for (const int id : mode_shape_.id) {
    file_.putAttribute(id, "_FillValue", NC_FILL_DOUBLE);
    file_.putAttribute(id, "coordinates", stage_.node_coordinates);
  }
  file_.endDefine();
  file_.put(mode_index, {0}, {count}, oneBased(count).data());
}

void NetcdfWriter::gatherModes(const ResultFrame& frame) {
  if (frame.frequencies.empty()) return;
  double* f = file_.slot<double>(angular_frequency_, stage_.count);
  std::copy(frame.frequencies.begin(), frame.frequencies.end(), f);
  requireAllFinite(f, mode_count_, path(),
                   [&](size_t m) { return "angular_frequency[mode " + std::to_string(m) + "]"; });
  const size_t nodes = node_count_;
  for (int k = 0; k < 3; ++k) {
    double* s = file_.slot<double>(mode_shape_.id[k], stage_.count);
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
  Records& r = frame.stage ? stage_ : time_;
  const model::State& s = *frame.state;
  const int step = frame.step_index + 1;
  const auto refuse = [&](const std::string& what) {
    throw std::runtime_error(path() + ": cannot write step \"" + frame.step_name + "\": " + what);
  };
  if (!frame.stage && time_.count > 0 && !(s.time > last_time_))
    refuse("its time " + formatNumber(s.time) + " is not after the last record's, " +
           formatNumber(last_time_) + " (the time coordinate increases strictly)");
  if (frame.stage &&
      std::find(staged_steps_.begin(), staged_steps_.end(), step) != staged_steps_.end())
    refuse("step " + std::to_string(step) + " has a stage record already");
  if (!frame.frequencies.empty() && !frame.stage)
    refuse("the modes of a modes step are stage records (frame.stage)");
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
  try {
    const auto gatherScalar = [&](int variable, const std::string& name, double value) {
      requireFinite(value, path(),
                    [&] { return name + "[record " + std::to_string(r.count) + "]"; });
      *file_.slot<double>(variable, r.count) = value;
    };
    gatherScalar(r.time, r.prefix + "time", s.time);
    gatherScalar(r.load_factor, r.prefix + "load_factor", s.load_factor);
    if (sea_ && !frame.stage)
      gatherScalar(wave_elevation_, "wave_elevation",
                   sea_->elevation(Eigen::Vector3d::Zero(), s.time));
    gatherNodal(r, r.displacement, s.displacement);
    gatherNodal(r, r.position, s.displacement, &reference_);
    gatherNodal(r, r.velocity, s.velocity);
    gatherNodal(r, r.reaction, frame.reactions);
    gatherTensions(r, frame);
    gatherResultants(r, frame);
    gatherModes(frame);  // a stage record's; other records keep the fill value there
    *file_.slot<int>(r.step_number, r.count) = step;
    char* name = file_.slot<char>(r.step_name, r.count);
    std::fill_n(std::copy(frame.step_name.begin(), frame.step_name.end(), name),
                name_length_ - frame.step_name.size(), '\0');
  } catch (...) {
    file_.drop();  // nothing of a refused record is written
    throw;
  }
  file_.commit();
  ++r.count;
  if (frame.stage)
    staged_steps_.push_back(step);
  else
    last_time_ = s.time;
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
