#include "apps/case/build/build_mesh.hpp"

#include "libstruct/element/axisymmetric_membrane.hpp"
#include "libstruct/element/spring_element.hpp"

namespace flexmoor::app {
namespace {

std::unique_ptr<element::Element> makeElement(const ElementSpec& e) {
  using Kind = ElementSpec::Kind;
  switch (e.kind) {
    case Kind::Cable:
      return element::makeCableElement(e.nodes, e.cable_section, e.quadrature);
    case Kind::MembraneTriangle:
      return element::makeMembraneElement("triangle", e.nodes, e.membrane_section, e.quadrature);
    case Kind::MembraneQuad:
      return element::makeMembraneElement("quad", e.nodes, e.membrane_section, e.quadrature);
    case Kind::AxisymmetricMembrane:
      return element::makeAxisymmetricMembrane(e.nodes, e.membrane_section, e.quadrature);
    case Kind::HoopCable:
      return std::make_unique<element::HoopCable>(e.nodes.front(), e.cable_section);
    case Kind::Spring:
      return std::make_unique<element::SpringElement>(e.nodes[0], e.nodes[1], e.stiffness,
                                                      e.rest_length, e.compression, e.damping);
    case Kind::PointMass:
      return std::make_unique<element::PointMassElement>(e.nodes.front(), e.mass);
  }
  return nullptr;
}

}  // namespace

void buildMesh(const MeshSpec& spec, model::Model& model) {
  model.addNodes(spec.reference);
  for (const ElementSpec& e : spec.elements) model.addElement(makeElement(e));
}

}  // namespace flexmoor::app
