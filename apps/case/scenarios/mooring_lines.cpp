#include "apps/case/scenarios/mooring_lines.hpp"

#include <cmath>

#include "apps/case/case_builder.hpp"
#include "apps/case/input/physical_range.hpp"
#include "apps/case/input/units.hpp"
#include "apps/common/format_number.hpp"
#include "libhydro/mooring/catenary_line.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);
const QuantityKind kMassPerLength{"a mass per length (like kg/m)", {1, -1, 0}};
const QuantityKind kWeightPerLength{"a force per length (like N/m)", {1, 0, -2}};

// `type:` of a line or a segment: a name of line_types (reported at the key when unknown; not
// when line_types itself has errors there).
std::optional<std::string> lineTypeRef(Input& in, Fields& f,
                                       const std::map<std::string, LineType>& types,
                                       const YAML::Node* type_map) {
  const YAML::Node* t = f.require("type");
  const auto type = t ? in.text(*t, f.path("type")) : std::nullopt;
  if (!type || types.count(*type)) return type;
  if (!type_map || !(*type_map)[*type]) {
    std::string names;
    for (const auto& entry : types) names += (names.empty() ? "" : ", ") + entry.first;
    in.diag.error(
        *t, f.path("type") + ": unknown line type (got '" + *type +
                "', expected one of line_types: " + (names.empty() ? "none defined" : names) + ")");
  }
  return std::nullopt;
}

// length, type, elements and order of a segment (or of a line of one type).
std::optional<MooringSegment> readSegment(Input& in, Fields& f,
                                          const std::map<std::string, LineType>& types,
                                          const YAML::Node* type_map) {
  MooringSegment s;
  const YAML::Node* l = f.require("length");
  const auto length =
      l ? in.quantity(*l, f.path("length"), kind::kLength, Limit::Positive) : std::nullopt;
  const auto type = lineTypeRef(in, f, types, type_map);
  s.elements = in.integerOr(f, "elements", 1, 20);
  s.order = in.integerOr(f, "order", 2, 3);
  if (s.order > 4)
    in.diag.error(f.keyLine("order"), f.path("order") + ": out of range (got " +
                                          std::to_string(s.order) +
                                          ", expected 2, 3 or 4 nodes an element)");
  if (!length || !type) return std::nullopt;
  s.length = *length;
  s.type = *type;
  return s;
}

std::optional<MooringAttachment> readAttachment(Input& in, const YAML::Node& item,
                                                const std::string& path, int segments) {
  Fields f(in.diag, item, path, {"at", "mass", "volume", "drag_area", "Ca"});
  MooringAttachment a;
  const YAML::Node* at = f.require("at");
  if (at && segments < 2) {
    in.diag.error(*at, f.path("at") + ": no connection point (got a line of " +
                           std::to_string(segments) +
                           " segment, expected segments: of two or more)");
    return std::nullopt;
  }
  const auto point = at ? in.integer(*at, f.path("at"), 1, segments - 1) : std::nullopt;
  const YAML::Node* m = f.find("mass");
  const YAML::Node* v = f.find("volume");
  const auto mass = m ? in.quantity(*m, f.path("mass"), kind::kMass, Limit::Positive)
                      : std::optional<double>(0.0);
  const auto volume = v ? in.quantity(*v, f.path("volume"), kind::kVolume, Limit::Positive)
                        : std::optional<double>(0.0);
  if (f.isMap() && !m && !v) {
    in.diag.error(item, path + ": nothing attached (expected mass:, volume: or both)");
    return std::nullopt;
  }
  for (const char* key : {"drag_area", "Ca"})
    if (const YAML::Node* n = f.find(key); n && !v) {
      in.diag.error(*n, f.path(key) +
                            ": given without volume: (expected the body's volume, "
                            "whose Morison loads it scales)");
      return std::nullopt;
    }
  const auto drag_area = in.quantityOr(f, "drag_area", kind::kArea, Limit::NonNegative, 0.0);
  const auto added_mass = in.quantityOr(f, "Ca", kind::kNumber, Limit::NonNegative, 0.0);
  if (!point || !mass || !volume) return std::nullopt;
  a.at = *point;
  a.mass = *mass;
  a.volume = *volume;
  a.drag_area = drag_area;
  a.added_mass = added_mass;
  return a;
}

}  // namespace

double MooringLine::length() const {
  double l = 0.0;
  for (const MooringSegment& s : segments) l += s.length;
  return l;
}

std::optional<LineType> readLineType(CaseBuilder& b, const MapEntry& e, double rho, double g) {
  Input& in = b.in;
  Diagnostics& diag = in.diag;
  Fields f(diag, e.value, childPath("line_types", e.key),
           {"diameter", "mass_per_length", "EA", "weight_in_water", "compression", "strain", "Cn",
            "Ct", "Ca", "CaAx", "tangential_drag_area", "per_length", "damping"});
  const auto need = [&](const char* key, const QuantityKind& kind) {
    const YAML::Node* n = f.require(key);
    return n ? in.quantity(*n, f.path(key), kind, Limit::Positive) : std::nullopt;
  };
  const auto d = need("diameter", kind::kLength);
  const auto m = need("mass_per_length", kMassPerLength);
  const auto ea = need("EA", kind::kForce);
  if (!d || !m || !ea) return std::nullopt;
  const double area = kPi * *d * *d / 4.0;
  // Its section's density, the mass per length over the area pi d^2 / 4.
  if (!inPhysicalRange(in, *f.find("mass_per_length"), f.path("mass_per_length"), *m / area,
                       kSectionDensityRange,
                       "a density of " + formatNumber(*m / area) + " " +
                           (in.units == UnitSystem::US ? "slug/ft^3" : "kg/m^3") +
                           " over the area pi d^2 / 4"))
    return std::nullopt;
  if (const YAML::Node* n = f.find("weight_in_water")) {
    const auto w = in.quantity(*n, f.path("weight_in_water"), kWeightPerLength);
    const double expected = (*m - rho * area) * g;
    if (w && rho > 0.0 && std::abs(*w - expected) > 1e-3 * std::abs(expected)) {
      diag.error(*n, f.path("weight_in_water") +
                         ": does not match the mass and diameter in this water (got " +
                         formatNumber(*w) + ", expected " + formatNumber(expected) +
                         " = (mass_per_length - rho pi d^2 / 4) g, within 0.1%)");
      return std::nullopt;
    }
  }
  // The mooring codes' law, N = EA (lambda - 1), unless `strain: green` (Eq. 2.53).
  std::optional<bool> engineering = true;
  if (const YAML::Node* s = f.find("strain"))
    engineering = in.choice<bool>(*s, f.path("strain"), {{"green", false}, {"engineering", true}});
  std::optional<material::Compression> compression = material::Compression::TensionOnly;
  if (const YAML::Node* c = f.find("compression"))
    compression = in.choice(*c, f.path("compression"), compressionChoices());
  const std::optional<LineHydroSpec> hydro = readLineHydro(b, f);
  element::CableSection damped;
  const YAML::Node* damping = f.find("damping");
  if (damping && !readLineDamping(b, *damping, f.path("damping"), damped)) return std::nullopt;
  if (!engineering || !compression || !hydro) return std::nullopt;
  LineType t = LineType::of(*d, *m, *ea, *hydro, *engineering, *compression);
  t.section.axial_damping = damped.axial_damping;
  t.section.damping_ratio = damped.damping_ratio;
  return t;
}

LineType LineType::of(double diameter, double mass_per_length, double ea, LineHydroSpec hydro,
                      bool engineering_strain, material::Compression compression) {
  LineType t;
  t.area = kPi * diameter * diameter / 4.0;
  t.mass_per_length = mass_per_length;
  t.ea = ea;
  t.diameter = diameter;
  const double E = ea / t.area;
  t.section.area = t.area;
  t.section.density = mass_per_length / t.area;
  t.section.material = engineering_strain
                           ? std::shared_ptr<const material::CableMaterial>(
                                 std::make_shared<material::EngineeringStrainCable>(E, compression))
                           : std::make_shared<material::LinearElasticCable>(E, compression);
  t.hydro = hydro;
  t.hydro.coefficients.diameter = diameter;
  return t;
}

std::optional<MooringLine> readMooringLine(Input& in, const YAML::Node& item,
                                           const std::string& path,
                                           const std::map<std::string, LineType>& types,
                                           const YAML::Node* type_map) {
  Fields f(
      in.diag, item, path,
      {"anchor", "fairlead", "length", "type", "elements", "order", "segments", "attachments"});
  MooringLine line;
  const YAML::Node* a = f.require("anchor");
  const YAML::Node* b = f.require("fairlead");
  const auto anchor = a ? in.vector3(*a, f.path("anchor"), kind::kLength) : std::nullopt;
  const auto fairlead = b ? in.vector3(*b, f.path("fairlead"), kind::kLength) : std::nullopt;
  bool ok = anchor && fairlead;
  const YAML::Node* segments = f.find("segments");
  line.has_segments = segments != nullptr;
  if (segments) {
    for (const char* key : {"length", "type", "elements", "order"})
      if (f.find(key)) {
        in.diag.error(f.keyLine(key), f.path(key) + ": given with segments: (expected either " +
                                          "length, type, elements and order of one line type, " +
                                          "or segments: each with its own)");
        ok = false;
      }
    const std::vector<YAML::Node> items = listItems(in.diag, *segments, f.path("segments"));
    if (segments->IsSequence() && items.empty()) {
      in.diag.error(*segments, f.path("segments") + ": empty (expected at least one segment)");
      ok = false;
    }
    for (size_t i = 0; i < items.size(); ++i) {
      Fields s(in.diag, items[i], itemPath(f.path("segments"), i),
               {"type", "length", "elements", "order"});
      const auto segment = readSegment(in, s, types, type_map);
      ok = ok && segment;
      if (segment) line.segments.push_back(*segment);
    }
    ok = ok && segments->IsSequence();
  } else {
    const auto segment = readSegment(in, f, types, type_map);
    ok = ok && segment;
    if (segment) line.segments.push_back(*segment);
  }
  if (const YAML::Node* n = f.find("attachments")) {
    if (!segments) {
      in.diag.error(*n, f.path("attachments") +
                            ": given without segments: (expected segments: "
                            "whose connection points carry them)");
      return std::nullopt;
    }
    const std::vector<YAML::Node> items = listItems(in.diag, *n, f.path("attachments"));
    for (size_t i = 0; i < items.size(); ++i) {
      const auto attachment =
          readAttachment(in, items[i], itemPath(f.path("attachments"), i),
                         segments->IsSequence() ? static_cast<int>(segments->size()) : 0);
      ok = ok && attachment;
      if (attachment) line.attachments.push_back(*attachment);
    }
  }
  if (!ok) return std::nullopt;
  line.anchor = *anchor;
  line.fairlead = *fairlead;
  return line;
}

bool checkStart(Diagnostics& diag, const YAML::Node& item, const std::string& path,
                const MooringLine& line, const std::map<std::string, LineType>& types, double rho,
                double g, double depth) {
  const double tolerance = 1e-6 * std::max(depth, line.length());
  for (const auto& [end, where] : {std::pair{&line.anchor, "anchor"}, {&line.fairlead, "fairlead"}})
    if (end->z() < -depth - tolerance) {
      diag.error(item,
                 path + "." + where + ": below the seabed (got z = " + formatNumber(end->z()) +
                     ", expected z >= " + formatNumber(-depth) + ", the bed at the water's depth)");
      return false;
    }
  hydro::CatenaryLineInputs in;
  const Eigen::Vector3d span = line.fairlead - line.anchor;
  in.horizontal_span = span.head<2>().norm();
  in.vertical_span = span.z();
  // The bed carries the line from an anchor on it, or between the parts hanging from a raised
  // anchor and the fairlead (libhydro/mooring/raised_anchor_catenary.hpp).
  in.seabed = true;
  in.anchor_height = line.anchor.z() <= -depth + tolerance ? 0.0 : line.anchor.z() + depth;
  for (const MooringSegment& s : line.segments) {
    const LineType& t = types.at(s.type);
    in.segments.push_back({s.length, (t.mass_per_length - rho * t.area) * g, t.ea});
  }
  in.connection_forces.assign(in.segments.size() - 1, 0.0);
  for (const MooringAttachment& a : line.attachments)
    in.connection_forces[a.at - 1] += (rho * a.volume - a.mass) * g;  // buoyancy less weight
  try {
    hydro::solveCatenary(in);
    return true;
  } catch (const hydro::CatenaryError& e) {
    diag.error(item, path + ": no catenary start: " + e.what());
    return false;
  }
}

}  // namespace flexmoor::app
