// loads: enclosed_fluid: of a case file, a liquid filling membranes (the dissertation's Example 9,
// libhydro/loads/enclosed_fluid.hpp):
//   {on: SURFACE or [SURFACES], density: RHO | specific_gravity: SG, pressure: P, at_z: Z}
// P is the liquid's gauge pressure at the elevation Z; with gravity it grows by rho_f g per unit
// depth below Z (at_z is then required). The specific gravity is relative to the water's density.
// Read with loads:, resolved after the water; put on the model once it is built
// (build_enclosed_fluid.hpp): its pressure as a surface load, its mass lumped at the wall's nodes
// as point_mass elements without weight.
#include <cmath>
#include <set>

#include "apps/case/build/build_enclosed_fluid.hpp"
#include "apps/case/case_builder.hpp"
#include "apps/common/format_number.hpp"

namespace flexmoor::app {
namespace {

// The liquid's density: given, or its specific gravity times the water's.
std::optional<double> fluidDensity(CaseBuilder& b, const PendingEnclosedFluid& s) {
  if (s.density) return s.density;
  if (b.ocean.has_water) return *s.specific_gravity * b.ocean.water.density;
  b.diag.error(s.line, s.where +
                           ".specific_gravity: needs the water it is relative to (got no water: "
                           "section, expected water: {density, depth}, or density: instead)");
  return std::nullopt;
}

// The magnitude of the case's gravity, which must act along -z (the liquid's pressure grows
// downwards); 0 without gravity.
std::optional<double> fluidGravity(CaseBuilder& b, const PendingEnclosedFluid& s) {
  const Eigen::Vector3d g = b.conditions.gravityVector();
  if (g.isZero(0.0)) return 0.0;
  if (g.z() < 0.0 && std::hypot(g.x(), g.y()) <= 1e-12 * g.norm()) {
    if (s.at_z) return g.norm();
    b.diag.error(s.line, s.where +
                             ": needs the elevation its pressure is given at, since gravity acts "
                             "(got no at_z, expected at_z: with a length)");
    return std::nullopt;
  }
  b.diag.error(s.line, s.where + ": needs gravity pointing down (got loads.gravity [" +
                           formatNumber(g.x()) + ", " + formatNumber(g.y()) + ", " +
                           formatNumber(g.z()) + "], expected [0, 0, -g] with g > 0: z is up)");
  return std::nullopt;
}

}  // namespace

void readEnclosedFluid(CaseBuilder& b, const YAML::Node& item, const std::string& path) {
  Fields f(b.diag, item, path, {"on", "density", "specific_gravity", "pressure", "at_z"});
  const YAML::Node* on = f.require("on");
  const YAML::Node* density = f.find("density");
  const YAML::Node* sg = f.find("specific_gravity");
  const YAML::Node* p = f.require("pressure");
  const YAML::Node* at_z = f.find("at_z");
  PendingEnclosedFluid s;
  bool ok = true;
  if (density && sg) {
    b.diag.error(*sg, path + ": give either density or specific_gravity, not both");
    ok = false;
  } else if (!density && !sg) {
    b.diag.error(item, path +
                           ": needs the liquid's density (got neither density nor "
                           "specific_gravity, expected one of them)");
    ok = false;
  }
  if (density)
    s.density = b.in.quantity(*density, f.path("density"), kind::kDensity, Limit::Positive);
  if (sg)
    s.specific_gravity =
        b.in.quantity(*sg, f.path("specific_gravity"), kind::kNumber, Limit::Positive);
  const auto pressure = p ? b.in.quantity(*p, f.path("pressure"), kind::kPressure) : std::nullopt;
  if (at_z) s.at_z = b.in.quantity(*at_z, f.path("at_z"), kind::kLength);
  const auto elements = on ? surfaceMembranes(b, *on, f.path("on")) : std::nullopt;
  ok = ok && elements && pressure && (!density || s.density) && (!sg || s.specific_gravity) &&
       (!at_z || s.at_z);
  if (!ok) return;
  s.elements = *elements;
  s.pressure = *pressure;
  s.line = lineOf(item);
  s.where = path;
  b.enclosed_fluids.push_back(std::move(s));
}

void resolveEnclosedFluids(CaseBuilder& b) {
  for (PendingEnclosedFluid& s : b.enclosed_fluids) {
    const auto density = fluidDensity(b, s);
    const auto g = fluidGravity(b, s);
    if (!density || !g) continue;
    s.fluid = hydro::EnclosedFluid{*density, s.pressure, s.at_z.value_or(0.0), *g};
    // The entries of its masses, one at each node of its wall (hydro::lumpedFluidMasses), for
    // the readers that follow; buildEnclosedFluids puts the masses on the model.
    std::set<int> wall;
    for (int e : s.elements) {
      const std::vector<int>& nodes = b.mesh.elementNodes(e);
      wall.insert(nodes.begin(), nodes.end());
    }
    for (size_t i = 0; i < wall.size(); ++i) {
      b.element_types.push_back("point_mass");
      b.origins.elements.push_back({s.line, s.where, ""});
    }
  }
}

void putEnclosedFluids(CaseBuilder& b) {
  for (const PendingEnclosedFluid& s : b.enclosed_fluids) {
    if (!s.fluid) {  // its density or gravity is wrong (reported); its wall may be too
      const std::string problem = enclosureProblem(b.c, s.elements, s.where);
      if (!problem.empty()) b.diag.error(s.line, problem);
      continue;
    }
    for (const SpecError& e : buildEnclosedFluids({{s.elements, *s.fluid, s.line, s.where}}, b.c))
      b.diag.error(e.line, e.message);
  }
}

}  // namespace flexmoor::app
