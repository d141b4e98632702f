// materials: and sections: of a case file.
#include "apps/case/case_builder.hpp"
#include "apps/case/input/physical_range.hpp"

namespace flexmoor::app {
namespace {

using material::Compression;

// Both laws of a material: the cable law (Eq. 2.53 / 2.54) and, where it has one, the membrane
// law (Eq. 2.41 / 2.42). A linear elastic material is a membrane material when it gives nu.
struct MaterialLaws {
  std::shared_ptr<const material::CableMaterial> cable;
  std::shared_ptr<const material::MembraneMaterial> membrane;
};

// `strain: green` (Eq. 2.53, the default) or `engineering` (N = EA (lambda - 1), the mooring
// codes' law) of a linear elastic material: whether it is engineering. A membrane (nu given)
// keeps Green's strain.
std::optional<bool> readEngineeringStrain(CaseBuilder& b, const Fields& f, bool membrane) {
  const YAML::Node* s = f.find("strain");
  if (!s) return false;
  const auto chosen =
      b.in.choice<bool>(*s, f.path("strain"), {{"green", false}, {"engineering", true}});
  if (chosen && *chosen && membrane) {
    b.diag.error(*s, f.path("strain") + ": engineering strain is a cable law (got it with nu, " +
                         "expected no nu: a membrane's linear law is Green's strain, Eq. 2.41)");
    return std::nullopt;
  }
  return chosen;
}

std::shared_ptr<const material::CableMaterial> linearCable(double E, Compression compression,
                                                           bool engineering) {
  if (engineering) return std::make_shared<material::EngineeringStrainCable>(E, compression);
  return std::make_shared<material::LinearElasticCable>(E, compression);
}

MaterialLaws readMaterial(CaseBuilder& b, const MapEntry& e) {
  const std::string path = childPath("materials", e.key);
  const std::string type = peekText(e.value, "type");
  Fields f(b.diag, e.value, path,
           type == "linear_elastic"
               ? std::vector<std::string>{"type", "E", "nu", "compression", "strain"}
           : type == "mooney_rivlin"
               ? std::vector<std::string>{"type", "C1", "C2", "compression"}
               : std::vector<std::string>{"type", "E", "nu", "C1", "C2", "compression", "strain"});
  const YAML::Node* t = f.require("type");
  if (!t) return {};
  if (type != "linear_elastic" && type != "mooney_rivlin") {
    b.in.choice<int>(*t, f.path("type"), {{"linear_elastic", 0}, {"mooney_rivlin", 1}});
    return {};
  }
  Compression compression = Compression::TensionOnly;
  if (const YAML::Node* c = f.find("compression")) {
    const auto chosen = b.in.choice(*c, f.path("compression"), compressionChoices());
    if (!chosen) return {};
    compression = *chosen;
  }
  if (type == "linear_elastic") {  // Eq. 2.53; in plane stress Eq. 2.41
    const YAML::Node* E = f.require("E");
    const auto modulus =
        E ? b.in.quantity(*E, f.path("E"), kind::kPressure, Limit::Positive) : std::nullopt;
    std::optional<double> nu;
    if (const YAML::Node* n = f.find("nu")) {
      nu = b.in.quantity(*n, f.path("nu"), kind::kNumber);
      if (nu && !(*nu > -1.0 && *nu < 0.5 + 1e-12)) {
        b.diag.error(*n, f.path("nu") + ": out of range (got " + n->Scalar() +
                             ", expected a Poisson ratio above -1 and at most 0.5)");
        nu.reset();
      }
      if (!nu) return {};
    }
    const std::optional<bool> engineering = readEngineeringStrain(b, f, nu.has_value());
    if (!modulus || !engineering) return {};
    MaterialLaws laws{linearCable(*modulus, compression, *engineering), nullptr};
    if (nu) laws.membrane = std::make_shared<material::LinearElasticPlaneStress>(*modulus, *nu);
    return laws;
  }
  // Eq. 2.54: the initial modulus is 6 (C1 + C2), which must be positive.
  const YAML::Node* n1 = f.require("C1");
  const YAML::Node* n2 = f.require("C2");
  const auto C1 = n1 ? b.in.quantity(*n1, f.path("C1"), kind::kPressure) : std::nullopt;
  const auto C2 = n2 ? b.in.quantity(*n2, f.path("C2"), kind::kPressure) : std::nullopt;
  if (!C1 || !C2) return {};
  if (!(*C1 + *C2 > 0.0)) {
    b.diag.error(*n1, path + ": out of range (got C1 = " + n1->Scalar() + ", C2 = " + n2->Scalar() +
                          ", expected C1 + C2 > 0: the initial modulus is 6 (C1 + C2))");
    return {};
  }
  return {std::make_shared<material::MooneyRivlinCable>(*C1, *C2, compression),
          std::make_shared<material::MooneyRivlinMembrane>(*C1, *C2)};  // Eq. 2.42
}

}  // namespace

// A cable section's `damping:`, axial Kelvin-Voigt damping (axial_damping.hpp): `BA:` in N*s, or
// `zeta:`, MoorDyn's negative BA input, turned into BA per element by the element from its length.
bool readLineDamping(CaseBuilder& b, const YAML::Node& n, const std::string& path,
                     element::CableSection& section) {
  Fields f(b.diag, n, path, {"BA", "zeta"});
  const YAML::Node* ba = f.find("BA");
  const YAML::Node* zeta = f.find("zeta");
  if (!f.isMap()) return false;
  if (ba && zeta) {
    b.diag.error(*zeta, path + ": give either BA (N*s) or zeta (MoorDyn's negative BA), not both");
    return false;
  }
  if (!ba && !zeta) {
    b.diag.error(n, path + ": missing key 'BA' (a coefficient in N*s) or 'zeta' (a damping ratio)");
    return false;
  }
  const YAML::Node& value = ba ? *ba : *zeta;
  const std::string key = ba ? "BA" : "zeta";
  const auto v = b.in.quantity(value, f.path(key), ba ? kind::kAxialDamping : kind::kNumber);
  if (!v) return false;
  if (*v < 0.0) {
    b.diag.error(value, f.path(key) + ": out of range (got " + value.Scalar() + ", expected >= 0" +
                            (ba ? "; MoorDyn's negative BA, a damping ratio, is given as "
                                  "damping: {zeta: ...}"
                                : "") +
                            ")");
    return false;
  }
  (ba ? section.axial_damping : section.damping_ratio) = *v;
  return true;
}

namespace {

// A cable section (`area:`) or a membrane section (`thickness:`, its material needing a membrane
// law).
std::optional<SectionSpec> readSection(CaseBuilder& b, const MapEntry& e) {
  Fields f(b.diag, e.value, childPath("sections", e.key),
           {"material", "area", "thickness", "density", "quadrature", "hydro", "damping"});
  SectionSpec s;
  const YAML::Node* area = f.find("area");
  const YAML::Node* thickness = f.find("thickness");
  if (area && thickness) {
    b.diag.error(*thickness, f.path() +
                                 ": give either area (a cable section) or thickness (a "
                                 "membrane section), not both");
    return std::nullopt;
  }
  s.is_membrane = thickness != nullptr;
  const YAML::Node* m = f.require("material");
  const auto name = m ? b.in.text(*m, f.path("material")) : std::nullopt;
  const auto found = name ? b.materials.find(*name) : b.materials.end();
  if (name && found == b.materials.end())
    b.diag.error(*m, f.path("material") + ": unknown material (got '" + *name + "', expected " +
                         nameList(b.materials) + ")");
  bool material_ok = found != b.materials.end() && found->second;
  if (material_ok && s.is_membrane) {
    s.membrane.material = b.membrane_materials[*name];
    if (!s.membrane.material) {
      b.diag.error(*m, f.path("material") + ": not a membrane material (got '" + *name +
                           "', linear_elastic without nu; expected mooney_rivlin or "
                           "linear_elastic with nu)");
      material_ok = false;
    }
  }
  if (material_ok) s.section.material = found->second;
  std::optional<double> size;
  if (s.is_membrane)
    size = b.in.quantity(*thickness, f.path("thickness"), kind::kLength, Limit::Positive);
  else if (!area && f.isMap())
    b.diag.error(f.node(), f.path() + ": missing key 'area' (or 'thickness' for a membrane)");
  else if (area)
    size = b.in.quantity(*area, f.path("area"), kind::kArea, Limit::Positive);
  const double density = b.in.quantityOr(f, "density", kind::kDensity, Limit::NonNegative, 0.0);
  if (const YAML::Node* d = f.find("density"))
    inPhysicalRange(b.in, *d, f.path("density"), density, kSectionDensityRange);
  s.section.area = s.is_membrane ? 0.0 : size.value_or(0.0);
  s.section.density = density;
  s.membrane.thickness = s.is_membrane ? size.value_or(0.0) : 0.0;
  s.membrane.density = density;
  if (const YAML::Node* q = f.find("quadrature"))
    s.quadrature = b.in.integer(*q, f.path("quadrature"), 0, 32).value_or(-1);
  bool hydro_ok = true;
  if (const YAML::Node* h = f.find("hydro")) {
    if (s.is_membrane) {
      b.diag.error(*h, f.path("hydro") +
                           ": Morison loads act on lines only (got hydro: on a membrane section "
                           "with thickness, expected it on a cable section with area)");
      hydro_ok = false;
    } else {
      s.hydro = readLineHydro(b, *h, f.path("hydro"));
      hydro_ok = s.hydro.has_value();
    }
  }
  bool damping_ok = true;
  if (const YAML::Node* d = f.find("damping")) {
    if (s.is_membrane) {
      b.diag.error(*d, f.path("damping") +
                           ": axial damping acts on lines only (got damping: on a membrane "
                           "section with thickness, expected it on a cable section with area)");
      damping_ok = false;
    } else {
      damping_ok = readLineDamping(b, *d, f.path("damping"), s.section);
      if (damping_ok && s.section.damping_ratio > 0.0 && !(density > 0.0)) {
        b.diag.error(*d, f.path("damping.zeta") +
                             ": needs the line's mass (got density 0, expected a section "
                             "density > 0: BA = zeta l sqrt(EA m))");
        damping_ok = false;
      }
    }
  }
  if (!material_ok || !size || s.quadrature < 0 || !hydro_ok || !damping_ok) return std::nullopt;
  return s;
}

}  // namespace

const std::vector<std::pair<std::string, Compression>>& compressionChoices() {
  static const std::vector<std::pair<std::string, Compression>> choices = {
      {"tension_only", Compression::TensionOnly}, {"carry", Compression::Carry}};
  return choices;
}

void readMaterials(CaseBuilder& b, const YAML::Node& n) {
  for (const MapEntry& e : mapEntries(b.diag, n, "materials")) {
    const MaterialLaws laws = readMaterial(b, e);
    b.materials[e.key] = laws.cable;
    b.membrane_materials[e.key] = laws.membrane;
  }
}

void readSections(CaseBuilder& b, const YAML::Node& n) {
  for (const MapEntry& e : mapEntries(b.diag, n, "sections")) b.sections[e.key] = readSection(b, e);
}

const SectionSpec* CaseBuilder::section(const YAML::Node& n, const std::string& path,
                                        SectionUse use) {
  const std::optional<std::string> name = in.text(n, path);
  if (!name) return nullptr;
  const auto found = sections.find(*name);
  if (found == sections.end()) {
    diag.error(
        n, path + ": unknown section (got '" + *name + "', expected " + nameList(sections) + ")");
    return nullptr;
  }
  if (!found->second) return nullptr;
  const bool membrane = use == SectionUse::Membrane;
  if (found->second->is_membrane != membrane) {
    diag.error(n, path + ": wrong kind of section (got '" + *name + "', a " +
                      (membrane ? "cable section with area" : "membrane section with thickness") +
                      ", expected a " +
                      (membrane ? "membrane section with thickness" : "cable section with area") +
                      ")");
    return nullptr;
  }
  return &*found->second;
}

}  // namespace flexmoor::app
