// materials: and sections: of a case file.
#include "apps/case/case_builder.hpp"

namespace flexmoor::app {
namespace {

using material::Compression;

std::shared_ptr<const material::CableMaterial> readMaterial(CaseBuilder& b, const MapEntry& e) {
  const std::string path = childPath("materials", e.key);
  const std::string type = peekText(e.value, "type");
  Fields f(b.diag, e.value, path,
           type == "linear_elastic" ? std::vector<std::string>{"type", "E", "compression"}
           : type == "mooney_rivlin"
               ? std::vector<std::string>{"type", "C1", "C2", "compression"}
               : std::vector<std::string>{"type", "E", "C1", "C2", "compression"});
  const YAML::Node* t = f.require("type");
  if (!t) return nullptr;
  if (type != "linear_elastic" && type != "mooney_rivlin") {
    b.in.choice<int>(*t, f.path("type"), {{"linear_elastic", 0}, {"mooney_rivlin", 1}});
    return nullptr;
  }
  Compression compression = Compression::TensionOnly;
  if (const YAML::Node* c = f.find("compression")) {
    const auto chosen = b.in.choice(*c, f.path("compression"), compressionChoices());
    if (!chosen) return nullptr;
    compression = *chosen;
  }
  if (type == "linear_elastic") {  // Eq. 2.53
    const YAML::Node* E = f.require("E");
    const auto modulus =
        E ? b.in.quantity(*E, f.path("E"), kind::kPressure, Limit::Positive) : std::nullopt;
    if (!modulus) return nullptr;
    return std::make_shared<material::LinearElasticCable>(*modulus, compression);
  }
  // Eq. 2.54: the initial modulus is 6 (C1 + C2), which must be positive.
  const YAML::Node* n1 = f.require("C1");
  const YAML::Node* n2 = f.require("C2");
  const auto C1 = n1 ? b.in.quantity(*n1, f.path("C1"), kind::kPressure) : std::nullopt;
  const auto C2 = n2 ? b.in.quantity(*n2, f.path("C2"), kind::kPressure) : std::nullopt;
  if (!C1 || !C2) return nullptr;
  if (!(*C1 + *C2 > 0.0)) {
    b.diag.error(*n1, path + ": out of range (got C1 = " + n1->Scalar() + ", C2 = " + n2->Scalar() +
                          ", expected C1 + C2 > 0: the initial modulus is 6 (C1 + C2))");
    return nullptr;
  }
  return std::make_shared<material::MooneyRivlinCable>(*C1, *C2, compression);
}

std::optional<SectionSpec> readSection(CaseBuilder& b, const MapEntry& e) {
  Fields f(b.diag, e.value, childPath("sections", e.key),
           {"material", "area", "density", "quadrature"});
  SectionSpec s;
  const YAML::Node* m = f.require("material");
  const auto name = m ? b.in.text(*m, f.path("material")) : std::nullopt;
  const auto found = name ? b.materials.find(*name) : b.materials.end();
  if (name && found == b.materials.end())
    b.diag.error(*m, f.path("material") + ": unknown material (got '" + *name + "', expected " +
                         nameList(b.materials) + ")");
  const bool material_ok = found != b.materials.end() && found->second;
  if (material_ok) s.section.material = found->second;
  const YAML::Node* area = f.require("area");
  const auto a =
      area ? b.in.quantity(*area, f.path("area"), kind::kArea, Limit::Positive) : std::nullopt;
  s.section.area = a.value_or(0.0);
  s.section.density = b.in.quantityOr(f, "density", kind::kDensity, Limit::NonNegative, 0.0);
  if (const YAML::Node* q = f.find("quadrature"))
    s.quadrature = b.in.integer(*q, f.path("quadrature"), 0, 32).value_or(-1);
  if (!material_ok || !a || s.quadrature < 0) return std::nullopt;
  return s;
}

}  // namespace

const std::vector<std::pair<std::string, Compression>>& compressionChoices() {
  static const std::vector<std::pair<std::string, Compression>> choices = {
      {"tension_only", Compression::TensionOnly}, {"carry", Compression::Carry}};
  return choices;
}

void readMaterials(CaseBuilder& b, const YAML::Node& n) {
  for (const MapEntry& e : mapEntries(b.diag, n, "materials"))
    b.materials[e.key] = readMaterial(b, e);
}

void readSections(CaseBuilder& b, const YAML::Node& n) {
  for (const MapEntry& e : mapEntries(b.diag, n, "sections")) b.sections[e.key] = readSection(b, e);
}

const SectionSpec* CaseBuilder::section(const YAML::Node& n, const std::string& path) {
  const std::optional<std::string> name = in.text(n, path);
  if (!name) return nullptr;
  const auto found = sections.find(*name);
  if (found == sections.end()) {
    diag.error(
        n, path + ": unknown section (got '" + *name + "', expected " + nameList(sections) + ")");
    return nullptr;
  }
  return found->second ? &*found->second : nullptr;
}

}  // namespace flexmoor::app
