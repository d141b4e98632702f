// The ocean sections of a case file: water:, waves:, current:, seabed:, bodies: and a section's
// hydro: (apps/problem/ocean_spec.hpp). Parsing and validation only; build_ocean.cpp makes the
// sea and its loads.
#include <algorithm>
#include <cmath>

#include "apps/case/case_builder.hpp"
#include "apps/case/input/physical_range.hpp"
#include "apps/case/read/read_fields.hpp"
#include "apps/case/read/read_sea.hpp"
#include "apps/case/read/read_seabed_friction.hpp"
#include "apps/common/format_number.hpp"
#include "libhydro/waves/dispersion.hpp"

namespace flexmoor::app {
namespace {

const double kPi = std::acos(-1.0);

// Miche's limit steepness of a regular wave: H / L <= 0.142 tanh(k h) (0.142 in deep water).
constexpr double kBreakingSteepness = 0.142;

// A value given in SI, in the case's system (the SI defaults of libhydro's structs).
double fromSi(CaseBuilder& b, double value, const QuantityKind& kind) {
  return value / systemScale(kind.dimension, b.in.units);
}

std::string lengthUnit(const CaseBuilder& b) { return unitNames(b.c.units).length; }

// Gravity for the water: the magnitude of `loads: gravity`, which must point down (-z, the sea's
// z is up); standard gravity when the case gives none.
std::optional<double> waterGravity(CaseBuilder& b, int line) {
  if (!b.gravity_given) return standardGravity(b.in.units);
  const Eigen::Vector3d g = b.conditions.gravityVector();
  const bool down = g.z() < 0.0 && std::hypot(g.x(), g.y()) <= 1e-12 * g.norm();
  if (down) return g.norm();
  b.diag.error(line, "water: needs gravity pointing down (got loads.gravity [" +
                         formatNumber(g.x()) + ", " + formatNumber(g.y()) + ", " +
                         formatNumber(g.z()) + "], expected [0, 0, -g] with g > 0: z is up)");
  return std::nullopt;
}

// water: {density, depth}, the density within kWaterDensityRange; false when it has errors.
bool readWater(CaseBuilder& b, const YAML::Node& n, int line, OceanSpec& h) {
  Fields f(b.diag, n, "water", {"density", "depth"});
  const auto density = requiredQuantity(b, f, "density", kind::kDensity, Limit::Positive);
  const auto depth = requiredQuantity(b, f, "depth", kind::kLength, Limit::Positive);
  const auto g = waterGravity(b, line);
  if (!density || !depth || !g) return false;
  if (!inPhysicalRange(b.in, *f.find("density"), f.path("density"), *density, kWaterDensityRange))
    return false;
  h.water = {*density, *depth, *g};
  h.bed = hydro::Bathymetry::flat(*depth);
  return true;
}

// One regular component {height, period, [heading: 0], [phase: 0]}, refused when it breaks.
std::optional<WaveSpec> readComponent(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                                      const hydro::Water& water) {
  Fields f(b.diag, n, path, {"height", "period", "heading", "phase"});
  const auto height = requiredQuantity(b, f, "height", kind::kLength, Limit::Positive);
  const auto period = requiredQuantity(b, f, "period", kind::kTime, Limit::Positive);
  const auto heading = optionalQuantity(b, f, "heading", kind::kNumber, Limit::Any, 0.0);
  const auto phase = optionalQuantity(b, f, "phase", kind::kNumber, Limit::Any, 0.0);
  if (!height || !period || !heading || !phase) return std::nullopt;
  const double k = hydro::waveNumber(2.0 * kPi / *period, water.depth, water.gravity);
  const double length = 2.0 * kPi / k;
  const double limit = kBreakingSteepness * length * std::tanh(k * water.depth);
  if (*height > limit) {
    const std::string unit = " " + lengthUnit(b);
    b.diag.error(
        *f.find("height"),
        f.path("height") + ": the wave cannot exist, it breaks (got H = " + formatNumber(*height) +
            unit + ", expected at most 0.142 L tanh(k h) = " + formatNumber(limit) + unit +
            ", Miche's limit, with L = " + formatNumber(length) + unit +
            " from the dispersion relation at T = " + formatNumber(*period) + " " +
            unitNames(b.c.units).time + " in depth h = " + formatNumber(water.depth) + unit + ")");
    return std::nullopt;
  }
  return WaveSpec{*height, *period, *heading, *phase, lineOf(n)};
}

// front: {start, [speed: group | phase], [ramp: 1 period]}.
std::optional<hydro::WaveFront> readFront(CaseBuilder& b, const YAML::Node& n,
                                          const std::string& path) {
  Fields f(b.diag, n, path, {"start", "speed", "ramp"});
  hydro::WaveFront front;
  const auto start = requiredQuantity(b, f, "start", kind::kLength, Limit::Any);
  const auto ramp =
      optionalQuantity(b, f, "ramp", kind::kNumber, Limit::NonNegative, front.ramp_periods);
  std::optional<hydro::WaveFront::Speed> speed = front.speed;
  if (const YAML::Node* s = f.find("speed"))
    speed = b.in.choice<hydro::WaveFront::Speed>(
        *s, f.path("speed"),
        {{"group", hydro::WaveFront::Speed::Group}, {"phase", hydro::WaveFront::Speed::Phase}});
  if (!start || !ramp || !speed) return std::nullopt;
  front.start = *start;
  front.ramp_periods = *ramp;
  front.speed = *speed;
  return front;
}

void readComponents(CaseBuilder& b, const YAML::Node& n, const std::string& path, OceanSpec& h) {
  const std::vector<YAML::Node> items = listItems(b.diag, n, path);
  for (size_t i = 0; i < items.size(); ++i)
    if (const auto wave = readComponent(b, items[i], itemPath(path, i), h.water))
      h.waves.push_back(*wave);
}

// waves: a list of regular components, or a map of them {components, ...}, of a spectrum
// {spectrum, ...} or of a record {measured, ...} (read_sea.cpp), each with
// [kinematics_above_mean], [front], [ramp_up] and [kinematics_reuse].
void readWaves(CaseBuilder& b, const YAML::Node& n, OceanSpec& h) {
  if (!n.IsMap()) return readComponents(b, n, "waves", h);
  const bool spectral = static_cast<bool>(n["spectrum"]),
             measured = static_cast<bool>(n["measured"]);
  std::vector<std::string> keys = {"kinematics_above_mean", "front", "ramp_up", "kinematics_reuse"};
  if (spectral) keys.insert(keys.end(), spectralSeaKeys().begin(), spectralSeaKeys().end());
  if (measured) keys.push_back("measured");
  if (!spectral && !measured) keys.push_back("components");
  Fields f(b.diag, n, "waves", keys);
  if (spectral && measured) {
    b.diag.error(f.keyLine("measured"),
                 "waves: give either spectrum (a sea state) or measured (a record), not both");
  } else if (spectral) {
    readSpectralSea(b, f, h);
  } else if (measured) {
    readMeasuredSea(b, *f.find("measured"), f.path("measured"), h);
  } else if (const YAML::Node* c = f.require("components")) {
    readComponents(b, *c, f.path("components"), h);
  }
  if (const YAML::Node* k = f.find("kinematics_above_mean"))
    h.surface = b.in.choice<hydro::SurfaceKinematics>(
                        *k, f.path("kinematics_above_mean"),
                        {{"wheeler", hydro::SurfaceKinematics::Wheeler},
                         {"constant", hydro::SurfaceKinematics::ConstantAboveMean}})
                    .value_or(h.surface);
  if (const YAML::Node* front = f.find("front")) h.front = readFront(b, *front, f.path("front"));
  if (const YAML::Node* r = f.find("ramp_up")) h.ramp = readRamp(b, *r, f.path("ramp_up"));
  if (const YAML::Node* r = f.find("kinematics_reuse"))
    h.kinematics_reuse =
        b.in.quantity(*r, f.path("kinematics_reuse"), kind::kLength, Limit::Positive);
}

// current: {[profile: uniform | power_law | table], speed | table, [heading: 0], power law:
// [exponent: 7], [reference_depth: the water's depth]}.
std::optional<hydro::CurrentProfile> readCurrent(CaseBuilder& b, const YAML::Node& n,
                                                 const hydro::Water& water) {
  const std::string profile = peekText(n, "profile");
  Fields f(b.diag, n, "current",
           profile == "power_law" ? std::vector<std::string>{"profile", "speed", "heading",
                                                             "exponent", "reference_depth"}
           : profile == "table"   ? std::vector<std::string>{"profile", "table", "heading"}
                                  : std::vector<std::string>{"profile", "speed", "heading"});
  if (const YAML::Node* p = f.find("profile");
      p && profile != "power_law" && profile != "table" && profile != "uniform") {
    b.in.choice<int>(*p, f.path("profile"), {{"uniform", 0}, {"power_law", 1}, {"table", 2}});
    return std::nullopt;
  }
  const auto heading = optionalQuantity(b, f, "heading", kind::kNumber, Limit::Any, 0.0);
  if (profile == "table") {
    const YAML::Node* t = f.require("table");
    const auto samples =
        t ? readIncreasingRows(b, *t, f.path("table"), {"z", kind::kLength}, {"U", kind::kVelocity})
          : std::nullopt;
    if (!samples || !heading) return std::nullopt;
    return hydro::CurrentProfile::table(*samples, *heading);
  }
  const auto speed = requiredQuantity(b, f, "speed", kind::kVelocity, Limit::NonNegative);
  if (profile != "power_law") {
    if (!speed || !heading) return std::nullopt;
    return hydro::CurrentProfile::uniform(*speed, *heading);
  }
  const auto exponent = optionalQuantity(b, f, "exponent", kind::kNumber, Limit::Positive, 7.0);
  const auto depth =
      optionalQuantity(b, f, "reference_depth", kind::kLength, Limit::Positive, water.depth);
  if (!speed || !heading || !exponent || !depth) return std::nullopt;
  return hydro::CurrentProfile::powerLaw(*speed, *exponent, *depth, *heading);
}

// grid: {x0, dx, y0, dy, z: [[z at (x0, y0), z at (x0 + dx, y0), ...], next y, ...]}.
std::optional<hydro::Bathymetry> readGrid(CaseBuilder& b, const YAML::Node& n,
                                          const std::string& path) {
  Fields f(b.diag, n, path, {"x0", "dx", "y0", "dy", "z"});
  const auto x0 = requiredQuantity(b, f, "x0", kind::kLength, Limit::Any);
  const auto dx = requiredQuantity(b, f, "dx", kind::kLength, Limit::Positive);
  const auto y0 = requiredQuantity(b, f, "y0", kind::kLength, Limit::Any);
  const auto dy = requiredQuantity(b, f, "dy", kind::kLength, Limit::Positive);
  const YAML::Node* z = f.require("z");
  if (!z) return std::nullopt;
  const std::vector<YAML::Node> rows = listItems(b.diag, *z, f.path("z"));
  std::vector<double> heights;
  bool ok = true;
  const size_t nx = rows.empty() || !rows[0].IsSequence() ? 0 : rows[0].size();
  for (size_t j = 0; j < rows.size() && ok; ++j) {
    const std::string row = itemPath(f.path("z"), j);
    if (!rows[j].IsSequence() || rows[j].size() != nx || nx < 2) {
      b.diag.error(rows[j], row + ": wrong row of heights (got " +
                                (rows[j].IsSequence() ? std::to_string(rows[j].size()) + " values"
                                                      : describeNode(rows[j])) +
                                ", expected a list of " + std::to_string(std::max<size_t>(nx, 2)) +
                                " lengths, as many as the first row and at least 2)");
      ok = false;
      break;
    }
    for (size_t i = 0; i < nx; ++i) {
      const auto h = b.in.quantity(rows[j][i], itemPath(row, i), kind::kLength);
      ok = ok && h.has_value();
      heights.push_back(h.value_or(0.0));
    }
  }
  if (ok && rows.size() < 2) {
    b.diag.error(*z, f.path("z") + ": too few rows (got " + std::to_string(rows.size()) +
                         ", expected at least 2 rows of constant y)");
    ok = false;
  }
  if (!ok || !x0 || !dx || !y0 || !dy) return std::nullopt;
  return hydro::Bathymetry::grid(*x0, *dx, static_cast<int>(nx), *y0, *dy,
                                 static_cast<int>(rows.size()), std::move(heights));
}

// seabed: {[stiffness], [damping], [friction: 0], [slip_speed], [slope: [sx, sy]] | [grid]}
// (friction: a number, or a map naming its law: read_seabed_friction.hpp);
// the defaults are MoorDyn's (seabed_contact.hpp), the bed flat at -depth unless a slope (through
// z = -depth at x = y = 0) or a grid says otherwise.
void readSeabed(CaseBuilder& b, const YAML::Node& n, OceanSpec& h) {
  Fields f(b.diag, n, "seabed",
           {"stiffness", "damping", "friction", "slip_speed", "slope", "grid"});
  const hydro::SeabedProperties si;
  const auto k = optionalQuantity(b, f, "stiffness", kind::kBedStiffness, Limit::NonNegative,
                                  fromSi(b, si.stiffness, kind::kBedStiffness));
  const auto c = optionalQuantity(b, f, "damping", kind::kBedDamping, Limit::NonNegative,
                                  fromSi(b, si.damping, kind::kBedDamping));
  hydro::SeabedProperties contact;
  const bool friction_ok = readSeabedFriction(b, f, contact);
  const YAML::Node* slope = f.find("slope");
  const YAML::Node* grid = f.find("grid");
  if (slope && grid) {
    b.diag.error(*grid, "seabed: give either slope (a plane) or grid (a table), not both");
    return;
  }
  if (slope) {
    if (!slope->IsSequence() || slope->size() != 2) {
      b.diag.error(*slope, f.path("slope") + ": expected [dz/dx, dz/dy], two plain numbers (got " +
                               describeNode(*slope) + ")");
      return;
    }
    const auto sx = b.in.quantity((*slope)[0], f.path("slope") + ".x", kind::kNumber);
    const auto sy = b.in.quantity((*slope)[1], f.path("slope") + ".y", kind::kNumber);
    if (!sx || !sy) return;
    h.bed = hydro::Bathymetry::plane(-h.water.depth, *sx, *sy);
  }
  if (grid) {
    const auto bed = readGrid(b, *grid, f.path("grid"));
    if (!bed) return;
    h.bed = *bed;
  }
  if (!k || !c || !friction_ok) return;
  contact.stiffness = *k;
  contact.damping = *c;
  h.contact = contact;
  h.has_contact = true;
}

// The mass a body puts at its node, from `mass:` or its weight in air `weight:` (over the
// water's gravity); 0 for none, nullopt when wrong.
std::optional<double> bodyMass(CaseBuilder& b, Fields& f, double g) {
  const YAML::Node* m = f.find("mass");
  const YAML::Node* w = f.find("weight");
  if (m && w) {
    b.diag.error(*w, f.path() + ": give either mass or weight (in air), not both");
    return std::nullopt;
  }
  if (m) return b.in.quantity(*m, f.path("mass"), kind::kMass, Limit::Positive);
  if (!w) return 0.0;
  const auto weight = b.in.quantity(*w, f.path("weight"), kind::kForce, Limit::Positive);
  return weight ? std::optional<double>(*weight / g) : std::nullopt;
}

// Whether a point mass sits at `node` already: an explicit point_mass element or a body's mass.
bool hasPointMass(const CaseBuilder& b, int node) {
  for (int e = 0; e < b.mesh.elementCount(); ++e)
    if (b.element_types[e] == "point_mass" && b.mesh.elementNodes(e).front() == node) return true;
  return std::any_of(b.body_masses.begin(), b.body_masses.end(),
                     [node](const PendingPointMass& m) { return m.node == node; });
}

// {node, type: sphere, diameter, Cd, [Ca: 0.5]} or {node, [type: point], volume,
// [drag_area: 0], [Ca: 0]}, with [mass] or [weight].
void readBody(CaseBuilder& b, const YAML::Node& item, const std::string& path, OceanSpec& h) {
  const std::string type = peekText(item, "type");
  const bool sphere = type == "sphere";
  Fields f(b.diag, item, path,
           sphere
               ? std::vector<std::string>{"node", "type", "diameter", "Cd", "Ca", "mass", "weight"}
               : std::vector<std::string>{"node", "type", "volume", "drag_area", "Ca", "mass",
                                          "weight"});
  if (const YAML::Node* t = f.find("type"); t && !sphere && type != "point") {
    b.in.choice<int>(*t, f.path("type"), {{"sphere", 0}, {"point", 1}});
    return;
  }
  const YAML::Node* n = f.require("node");
  const int node = n ? nodeRef(b, *n, f.path("node")).value_or(-1) : -1;
  std::optional<hydro::PointBody> body;
  if (sphere) {
    const auto d = requiredQuantity(b, f, "diameter", kind::kLength, Limit::Positive);
    const auto cd = requiredQuantity(b, f, "Cd", kind::kNumber, Limit::NonNegative);
    const auto ca = optionalQuantity(b, f, "Ca", kind::kNumber, Limit::NonNegative, 0.5);
    if (d && cd && ca) body = hydro::PointBody::sphere(*d, *cd, *ca);
  } else {
    const auto volume = requiredQuantity(b, f, "volume", kind::kVolume, Limit::Positive);
    const auto area = optionalQuantity(b, f, "drag_area", kind::kArea, Limit::NonNegative, 0.0);
    const auto ca = optionalQuantity(b, f, "Ca", kind::kNumber, Limit::NonNegative, 0.0);
    if (volume && area && ca) body = hydro::PointBody{*volume, *area, *ca, 0.0};
  }
  const auto mass = bodyMass(b, f, h.water.gravity);
  if (node < 0 || !body || !mass) return;
  if (*mass > 0.0 && hasPointMass(b, node)) {
    b.diag.error(item, path + ": node " + std::to_string(b.c.node_ids[node]) +
                           " has a point_mass element already (got a second mass, expected the "
                           "mass given once: drop mass/weight here or the point_mass)");
    return;
  }
  h.bodies.push_back({node, *body, lineOf(item), path});
  if (*mass > 0.0) b.body_masses.push_back({node, *mass, lineOf(item), path});
}

// What needs water, refused without it: "waves: needs water: (...)".
void refuseWithoutWater(CaseBuilder& b, int line, const std::string& what) {
  b.diag.error(line, what +
                         ": needs the water it acts in (got no water: section, expected "
                         "water: {density, depth})");
}

}  // namespace

std::optional<LineHydroSpec> readLineHydro(CaseBuilder& b, const YAML::Node& n,
                                           const std::string& path) {
  Fields f(b.diag, n, path,
           {"diameter", "Cn", "Ct", "Ca", "CaAx", "tangential_drag_area", "per_length"});
  return readLineHydro(b, f);
}

std::optional<LineHydroSpec> readLineHydro(CaseBuilder& b, Fields& f) {
  LineHydroSpec s;
  s.line = lineOf(f.node());
  hydro::MorisonCoefficients& c = s.coefficients;
  const auto d = requiredQuantity(b, f, "diameter", kind::kLength, Limit::Positive);
  const auto cn = requiredQuantity(b, f, "Cn", kind::kNumber, Limit::NonNegative);
  const auto ca = requiredQuantity(b, f, "Ca", kind::kNumber, Limit::NonNegative);
  const auto ct = optionalQuantity(b, f, "Ct", kind::kNumber, Limit::NonNegative, 0.0);
  const auto ca_axial = optionalQuantity(b, f, "CaAx", kind::kNumber, Limit::NonNegative, 0.0);
  using Area = hydro::MorisonCoefficients::TangentialDragArea;
  std::optional<Area> area = Area::Perimeter;
  if (const YAML::Node* a = f.find("tangential_drag_area"))
    area = b.in.choice<Area>(*a, f.path("tangential_drag_area"),
                             {{"perimeter", Area::Perimeter}, {"diameter", Area::Diameter}});
  std::optional<model::LengthMeasure> measure = s.per_length;
  if (const YAML::Node* p = f.find("per_length"))
    measure = b.in.choice<model::LengthMeasure>(*p, f.path("per_length"),
                                                {{"deformed", model::LengthMeasure::Current},
                                                 {"unstretched", model::LengthMeasure::Reference}});
  if (!d || !cn || !ca || !ct || !ca_axial || !area || !measure) return std::nullopt;
  c = {*d, *cn, *ct, *ca, *ca_axial, *area};
  s.per_length = *measure;
  return s;
}

void readOcean(CaseBuilder& b, const Fields& top) {
  OceanSpec& h = b.ocean;
  const YAML::Node* water = top.find("water");
  bool water_ok = false;
  if (water) {
    h.water_line = top.keyLine("water");
    water_ok = readWater(b, *water, h.water_line, h);
  }
  h.has_water = water_ok;
  // Without water (or with a broken one, already reported) nothing else can be read.
  if (!water_ok) {
    if (water) return;
    for (const char* key : {"waves", "current", "seabed", "bodies"})
      if (top.find(key)) refuseWithoutWater(b, top.keyLine(key), key);
    for (const auto& [name, s] : b.sections)
      if (s && s->hydro) refuseWithoutWater(b, s->hydro->line, "sections." + name + ".hydro");
    for (const WavePressureSpec& w : h.wave_pressures) refuseWithoutWater(b, w.line, w.where);
    return;
  }
  if (const YAML::Node* n = top.find("waves")) readWaves(b, *n, h);
  if (const YAML::Node* n = top.find("current")) h.current = readCurrent(b, *n, h.water);
  if (const YAML::Node* n = top.find("seabed")) readSeabed(b, *n, h);
  if (const YAML::Node* n = top.find("bodies")) {
    const std::vector<YAML::Node> items = listItems(b.diag, *n, "bodies");
    for (size_t i = 0; i < items.size(); ++i) readBody(b, items[i], itemPath("bodies", i), h);
  }
}

}  // namespace flexmoor::app
