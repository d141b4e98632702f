#include "tests/support/cable_models.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "libstruct/model/assembler.hpp"

namespace flexmoor::test {

element::CableSection linearElasticSection(double E, double area, double density,
                                           material::Compression compression) {
  element::CableSection section;
  section.area = area;
  section.density = density;
  section.material = std::make_shared<material::LinearElasticCable>(E, compression);
  return section;
}

std::vector<int> addStraightCable(model::Model& model, int first, int last, int elements,
                                  int nodes_per_element, const element::CableSection& section,
                                  int quadrature_points) {
  if (elements < 1 || nodes_per_element < 2 || nodes_per_element > 4)
    throw std::invalid_argument("addStraightCable: need >= 1 element of 2, 3 or 4 nodes");
  const Eigen::Vector3d a = model.reference().col(first);
  const Eigen::Vector3d b = model.reference().col(last);
  const int intervals = elements * (nodes_per_element - 1);
  std::vector<int> nodes{first};
  for (int k = 1; k < intervals; ++k)
    nodes.push_back(model.addNode(a + (b - a) * (static_cast<double>(k) / intervals)));
  nodes.push_back(last);
  for (int e = 0; e < elements; ++e) {
    const auto begin = nodes.begin() + e * (nodes_per_element - 1);
    model.addElement(element::makeCableElement(std::vector<int>(begin, begin + nodes_per_element),
                                               section, quadrature_points));
  }
  return nodes;
}

void pin(model::Model& model, int node) {
  for (int k = 0; k < 3; ++k) model.constrain(node, k);
}

int SuspendedCable::centreNode() const {
  if (nodes.size() % 2 == 0)
    throw std::logic_error("the mesh has no node at mid-length (even node count)");
  return nodes[nodes.size() / 2];
}

SuspendedCable makeSuspendedCable(const SuspendedCableInputs& in, int elements,
                                  int nodes_per_element, material::Compression compression,
                                  int quadrature_points) {
  SuspendedCable cable;
  cable.model = std::make_unique<model::Model>();
  model::Model& m = *cable.model;
  const int left = m.addNode(Eigen::Vector3d::Zero());
  const int right = m.addNode(Eigen::Vector3d(in.unstretched_length, 0.0, 0.0));
  cable.nodes = addStraightCable(
      m, left, right, elements, nodes_per_element,
      linearElasticSection(in.youngs_modulus, in.area, in.density, compression), quadrature_points);
  for (int n : cable.nodes) m.constrain(n, 1);  // planar: every y dof fixed
  m.constrain(left, 0);
  m.constrain(left, 2);
  m.constrain(right, 2);
  m.addNodalLoad(right, Eigen::Vector3d(in.horizontal_force, 0.0, 0.0));
  m.setGravity(Eigen::Vector3d(0.0, 0.0, -in.gravity));
  m.numberEquations();
  return cable;
}

solve::RelaxationOptions exampleOneRelaxation() {
  solve::RelaxationOptions o;
  o.tolerance = 1e-3;
  o.damping = 1.0e4;
  o.initial_damping_factor = 0.01;
  o.decrement = 1.0;
  return o;
}

SagAndMovement relaxSuspendedCable(const SuspendedCable& cable,
                                   const solve::RelaxationOptions& options) {
  const model::Assembler assembler(*cable.model);
  model::State state = cable.model->initialState();
  SagAndMovement r;
  r.report = solve::relax(assembler, state, options);
  r.centre_sag = -state.displacement(2, cable.centreNode());
  r.support_movement = -state.displacement(0, cable.rightNode());
  r.least_point_tension = std::numeric_limits<double>::infinity();
  for (const element::ElementResult& e : assembler.elementResults(state))
    for (double t : e.point_tension) r.least_point_tension = std::min(r.least_point_tension, t);
  return r;
}

}  // namespace flexmoor::test
