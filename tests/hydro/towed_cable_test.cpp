// A straight cable towed and accelerated through still water (Morison's load, Appendix E;
// docs/theory.md), integrated by the cable elements and summed by the assembler: the closed forms of a
// uniform load on a line of length L,
//   towed broadside at U:       1/2 rho Cn d L U^2 against the motion,
//   towed along its axis at U:  1/2 rho (pi d) Ct L U^2 (MoorDyn's area, the default) or
//                               1/2 rho d Ct L U^2 (the dissertation's, Eq. E.2),
//   accelerated at a:           rho A Ca L a (normal), rho A CaAx L a (axial), against it,
//   always:                     the buoyancy rho g A L upwards,
// with L the deformed length (the dissertation's Eq. E.1, the default) or the unstretched one
// (MoorDyn). The line lies horizontally along (0.6, 0.8, 0) 20 m down in 100 m of water, four
// 3-node elements (the integrand is constant, so Gauss integration is exact). Tolerance 1e-14
// relative (measured at most 4e-16: round-off of a sum of a few dozen terms).
#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/ocean_models.hpp"

namespace flexmoor::test {
namespace {

using Eigen::Vector3d;

const double kPi = std::acos(-1.0);
constexpr double kLength = 10.0, kU = 1.3, kA = 0.7, kTolerance = 1e-14;
const Vector3d kAxis(0.6, 0.8, 0.0), kBroadside(-0.8, 0.6, 0.0);

hydro::MorisonCoefficients coefficients() {
  hydro::MorisonCoefficients c;
  c.diameter = 0.1;
  c.cn = 1.2;
  c.ct = 0.02;
  c.ca = 1.0;
  c.ca_axial = 0.4;
  return c;
}

struct Towed {
  OceanLine line;
  std::unique_ptr<model::Assembler> assembler;
  model::State state;
};

// The line, stretched uniformly by `stretch` along its axis, every node moving at `velocity` and
// accelerating at `acceleration`.
Towed towed(const hydro::MorisonCoefficients& c, model::LengthMeasure measure, double stretch,
            const Vector3d& velocity, const Vector3d& acceleration) {
  OceanLineInputs in;
  in.start = Vector3d(0.0, 0.0, -20.0);
  in.end = in.start + kLength * kAxis;
  in.elements = 4;
  in.nodes_per_element = 3;
  in.morison = c;
  in.measure = measure;
  in.sea = stillWater(100.0);
  Towed t{makeOceanLine(in), nullptr, model::State()};
  t.line.model->numberEquations();
  t.assembler = std::make_unique<model::Assembler>(*t.line.model);
  t.state = t.line.model->initialState();
  const model::NodalField& X = t.line.model->reference();
  for (int n = 0; n < X.cols(); ++n) {
    t.state.displacement.col(n) = (stretch - 1.0) * (X.col(n) - in.start);
    t.state.velocity.col(n) = velocity;
    t.state.acceleration.col(n) = acceleration;
  }
  t.state.load_factor = 1.0;
  return t;
}

double area(const hydro::MorisonCoefficients& c) { return 0.25 * kPi * c.diameter * c.diameter; }

Vector3d buoyancy(const hydro::MorisonCoefficients& c, double length) {
  return kSeaWaterDensity * kStandardGravity * area(c) * length * Vector3d::UnitZ();
}

void expectNear(const Vector3d& got, const Vector3d& expected) {
  EXPECT_LT((got - expected).norm(), kTolerance * expected.norm())
      << "got " << got.transpose() << ", expected " << expected.transpose();
}

TEST(TowedCable, BroadsideDragIsHalfRhoCnDLU2) {
  const hydro::MorisonCoefficients c = coefficients();
  const Towed t = towed(c, model::LengthMeasure::Current, 1.0, kU * kBroadside, Vector3d::Zero());
  const double drag = 0.5 * kSeaWaterDensity * c.cn * c.diameter * kLength * kU * kU;
  expectNear(totalExternalLoad(*t.assembler, t.state), -drag * kBroadside + buoyancy(c, kLength));
}

TEST(TowedCable, AxialDragUsesThePerimeterOrTheDiameter) {
  hydro::MorisonCoefficients c = coefficients();
  const double skin = 0.5 * kSeaWaterDensity * c.ct * kLength * kU * kU;
  const Towed moordyn = towed(c, model::LengthMeasure::Current, 1.0, kU * kAxis, Vector3d::Zero());
  expectNear(totalExternalLoad(*moordyn.assembler, moordyn.state),
             -skin * kPi * c.diameter * kAxis + buoyancy(c, kLength));
  c.tangential_area = hydro::MorisonCoefficients::TangentialDragArea::Diameter;
  const Towed dissertation =
      towed(c, model::LengthMeasure::Current, 1.0, kU * kAxis, Vector3d::Zero());
  expectNear(totalExternalLoad(*dissertation.assembler, dissertation.state),
             -skin * c.diameter * kAxis + buoyancy(c, kLength));
}

// Stretched by 2%: per deformed length every term grows with the length, per unstretched length
// none does.
TEST(TowedCable, StretchedLineCarriesItsLoadPerTheChosenLength) {
  const hydro::MorisonCoefficients c = coefficients();
  const double stretch = 1.02;
  const double drag = 0.5 * kSeaWaterDensity * c.cn * c.diameter * kU * kU;
  for (const auto measure : {model::LengthMeasure::Current, model::LengthMeasure::Reference}) {
    const double length = measure == model::LengthMeasure::Current ? stretch * kLength : kLength;
    const Towed t = towed(c, measure, stretch, kU * kBroadside, Vector3d::Zero());
    expectNear(totalExternalLoad(*t.assembler, t.state),
               -drag * length * kBroadside + buoyancy(c, length));
  }
}

TEST(TowedCable, AcceleratedLineCarriesItsAddedMass) {
  const hydro::MorisonCoefficients c = coefficients();
  const double mass = kSeaWaterDensity * area(c) * kLength * kA;  // rho A L a
  const Towed normal =
      towed(c, model::LengthMeasure::Current, 1.0, Vector3d::Zero(), kA * Vector3d(0.0, 0.0, 1.0));
  expectNear(totalExternalLoad(*normal.assembler, normal.state),
             -c.ca * mass * Vector3d::UnitZ() + buoyancy(c, kLength));
  const Towed axial = towed(c, model::LengthMeasure::Current, 1.0, Vector3d::Zero(), kA * kAxis);
  expectNear(totalExternalLoad(*axial.assembler, axial.state),
             -c.ca_axial * mass * kAxis + buoyancy(c, kLength));
}

}  // namespace
}  // namespace flexmoor::test
