#include "tests/support/fluid_tube.hpp"

#include <cmath>

#include "libstruct/element/membrane_element.hpp"
#include "libstruct/material/membrane_material.hpp"

namespace flexmoor::test {

FluidTube makeFluidTube(const FluidTubeInputs& in) {
  const double pi = std::acos(-1.0);
  FluidTube t;
  t.model = std::make_unique<model::Model>();
  model::Model& m = *t.model;
  const int n = in.elements;
  const auto at = [&](int k, double y) {  // ring index k: angle 90 deg - k pi / n
    const double theta = pi / 2.0 - k * pi / n;
    return Eigen::Vector3d(in.radius * std::cos(theta), y,
                           in.centre_z + in.radius * std::sin(theta));
  };
  for (int k = 0; k < 2 * n; ++k) t.ring0.push_back(m.addNode(at(k, 0.0)));
  for (int k = 0; k < 2 * n; ++k) t.ring1.push_back(m.addNode(at(k, in.length)));
  for (int k = 0; k < n; ++k) t.middle.push_back(m.addNode(at(2 * k, 0.5 * in.length)));
  const element::MembraneSection section{
      in.thickness, in.density,
      std::make_shared<material::LinearElasticPlaneStress>(in.youngs_modulus, in.poisson)};
  for (int k = 0; k < n; ++k) {
    const int a = 2 * k, mid = 2 * k + 1, b = (2 * k + 2) % (2 * n);
    // Q8: corners counter-clockwise in (xi, eta), xi around, eta along y; then the mid-sides.
    const std::vector<int> nodes = {t.ring0[a],   t.ring0[b],   t.ring1[b],
                                    t.ring1[a],   t.ring0[mid], t.middle[(k + 1) % n],
                                    t.ring1[mid], t.middle[k]};
    t.membranes.push_back(m.addElement(element::makeMembraneElement("quad", nodes, section)));
  }
  return t;
}

}  // namespace flexmoor::test
