// A buoyant sphere released from rest deep in still water rises to its terminal velocity: a point
// mass (PointMassElement, weight W = m g from the model's gravity) at a free node with the water's
// load on it (BodyNodeLoad: buoyancy B = rho g V, quadratic drag 1/2 rho CdA |v| v, added mass
// rho V Ca), integrated by Newmark (average acceleration) with the added mass and the drag's
// damping in the effective tangent. Reference: the closed form of
//   (m + rho V Ca) v' = B - W - 1/2 rho CdA v^2,  v(0) = 0:
//   v(t) = v_t tanh(k t),  v_t = sqrt(2 (B - W) / (rho CdA)),  k = (B - W) / ((m + rho V Ca) v_t).
// A 0.5 m sphere of density 500 kg/m^3, Cd 1, Ca 1/2: v_t = 1.83 m/s, k = 2.78 1/s; 3 s (8 / k)
// at dt = 0.01 s (k dt = 0.028; the trapezoidal rule's error is O((k dt)^2)). Metric: the largest
// |v_n - v(t_n)| / v(t_n) over every step. Required: 0.5%; measured 1.3e-4, held to 2e-4.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "libhydro/loads/body_node_load.hpp"
#include "libstruct/element/spring_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/newmark.hpp"
#include "tests/support/ocean_models.hpp"

namespace flexmoor::test {
namespace {

using Eigen::Vector3d;

TEST(SphereTerminalVelocity, RiseSpeedFollowsTheQuadraticDragClosedForm) {
  const double diameter = 0.5, density = 500.0, cd = 1.0, ca = 0.5;
  const hydro::PointBody sphere = hydro::PointBody::sphere(diameter, cd, ca);
  const double rho = kSeaWaterDensity, g = kStandardGravity, mass = density * sphere.volume;

  model::Model m;
  const int node = m.addNode(Vector3d(0.0, 0.0, -50.0));
  m.addElement(std::make_unique<element::PointMassElement>(node, mass));
  m.setGravity(Vector3d(0.0, 0.0, -g));
  m.addNodeLoad(std::make_shared<hydro::BodyNodeLoad>(node, sphere, stillWater(1000.0)));
  m.constrain(node, 0);
  m.constrain(node, 1);
  m.numberEquations();
  const model::Assembler assembler(m);

  const double net = (rho * sphere.volume - mass) * g;  // B - W
  const double v_t = std::sqrt(2.0 * net / (rho * sphere.drag_area));
  const double k = net / ((mass + rho * sphere.volume * ca) * v_t);

  solve::DynamicOptions options;
  options.schedule = {{0.01, 300}};
  options.load_factor = 1.0;
  model::State s = m.initialState();
  double worst = 0.0, worst_of_terminal = 0.0;
  int steps = 0;
  solve::integrate(assembler, s, options, {}, [&](const model::State& at) {
    const double exact = v_t * std::tanh(k * at.time);
    const double error = std::abs(at.velocity(2, node) - exact);
    worst = std::max(worst, error / exact);
    worst_of_terminal = std::max(worst_of_terminal, error / v_t);
    ++steps;
  });
  EXPECT_EQ(steps, 300);
  EXPECT_NEAR(s.velocity(2, node) / v_t, 1.0, 1e-3);  // 3 s = 8 / k: at terminal speed
  EXPECT_LT(worst, 2e-4);
  std::cout << "sphere: v_t " << v_t << " m/s, k " << k << " 1/s; largest |v - v(t)| / v(t) "
            << worst << ", / v_t " << worst_of_terminal << '\n';
}

}  // namespace
}  // namespace flexmoor::test
