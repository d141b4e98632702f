#include "tests/support/membrane_models.hpp"

#include <cmath>
#include <vector>

#include "libstruct/element/axisymmetric_membrane.hpp"
#include "libstruct/material/membrane_material.hpp"

namespace flexmoor::test {

double tubeStretchAtPressure(const TubeInputs& t, double pressure) {
  const double limit = 2.0 * (t.C1 + t.C2) * t.thickness / t.radius;
  return std::pow(1.0 - pressure / limit, -0.25);  // inverse of p(lambda), closed form
}

namespace {

element::MembraneSection tubeSection(const TubeInputs& t) {
  return {t.thickness, 1.0, std::make_shared<material::MooneyRivlinMembrane>(t.C1, t.C2)};
}

void pressuriseAll(model::Model& m) {
  std::vector<int> all(m.elementCount());
  for (int e = 0; e < m.elementCount(); ++e) all[e] = e;
  m.addPressure({all, 1.0, nullptr});
}

}  // namespace

std::unique_ptr<model::Model> quarterTube(const TubeInputs& t, int elements,
                                          int nodes_per_element) {
  auto m = std::make_unique<model::Model>();
  const int p = nodes_per_element == 4 ? 1 : 2;  // node intervals per element edge
  const int around = elements * p + 1, along = p + 1;
  const double pi = std::acos(-1.0);
  std::vector<std::vector<int>> id(around, std::vector<int>(along, -1));
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < along; ++j) {
      if (p == 2 && i % 2 == 1 && j == 1) continue;  // serendipity: no centre node
      const double theta = 0.5 * pi * i / (around - 1);
      id[i][j] = m->addNode(
          {t.radius * std::cos(theta), t.radius * std::sin(theta), t.length * j / (along - 1)});
    }
  for (int e = 0; e < elements; ++e) {
    const int i = e * p;
    // xi around the tube, eta along the axis: y,xi x y,eta points outwards
    std::vector<int> n = {id[i][0], id[i + p][0], id[i + p][p], id[i][p]};
    if (p == 2) n.insert(n.end(), {id[i + 1][0], id[i + 2][1], id[i + 1][2], id[i][1]});
    m->addElement(element::makeMembraneElement("quad", n, tubeSection(t)));
  }
  pressuriseAll(*m);
  for (int n = 0; n < m->nodeCount(); ++n) {
    m->constrain(n, 2);
    if (std::abs(m->reference()(1, n)) < 1e-9 * t.radius) m->constrain(n, 1);
    if (std::abs(m->reference()(0, n)) < 1e-9 * t.radius) m->constrain(n, 0);
  }
  m->numberEquations();
  return m;
}

std::unique_ptr<model::Model> axisymmetricTube(const TubeInputs& t, int elements,
                                               int nodes_per_element) {
  auto m = std::make_unique<model::Model>();
  const int nodes = elements * (nodes_per_element - 1) + 1;
  for (int i = 0; i < nodes; ++i) m->addNode({t.radius, 0.0, t.length * i / (nodes - 1)});
  for (int e = 0; e < elements; ++e) {
    std::vector<int> n;
    for (int k = 0; k < nodes_per_element; ++k) n.push_back(e * (nodes_per_element - 1) + k);
    m->addElement(element::makeAxisymmetricMembrane(n, tubeSection(t)));
  }
  pressuriseAll(*m);
  for (int n = 0; n < nodes; ++n) {
    m->constrain(n, 1);
    m->constrain(n, 2);
  }
  m->numberEquations();
  return m;
}

}  // namespace flexmoor::test
