// The residual a Newton solve can reach is bounded below by round-off: positions are known to
// eps |x|, and a stiff element turns that into a force. A 100 m steel chain of 5,000 elements has
// a floor above the default residual tolerance (1e-8), all the more 2 km from the origin; the
// solvers must recognise it, converge
// (the displacement test of Eq. 5.1 still holds), and give the right answer. Without the floor,
// Newton stalls at a relative residual of 9e-6 here and the solve is reported as failed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "libstruct/element/cable_element.hpp"
#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "libstruct/solve/newmark.hpp"
#include "libstruct/solve/static_solver.hpp"

namespace flexmoor {
namespace {

constexpr int kElements = 5000;
// The chain lies 2 km from the origin, as a mooring line of a farm in site coordinates does.
constexpr double kLength = 100.0, kOffset = 2000.0, kE = 2.0e11, kArea = 0.01, kStretch = 1.0e-4;

// Both ends pinned, the right one pulled out by kStretch * kLength (load factor 1); the other
// nodes free in x, y and z.
std::unique_ptr<model::Model> stiffChain() {
  auto m = std::make_unique<model::Model>();
  for (int i = 0; i <= kElements; ++i) m->addNode({kOffset + kLength * i / kElements, 0.0, 0.0});
  const element::CableSection section{
      kArea, 7850.0,
      std::make_shared<material::LinearElasticCable>(kE, material::Compression::Carry)};
  for (int e = 0; e < kElements; ++e) m->addElement(element::makeCableElement({e, e + 1}, section));
  for (int k = 0; k < 3; ++k) {
    m->constrain(0, k);
    m->constrain(kElements, k, k == 0 ? kStretch * kLength : 0.0);
  }
  m->numberEquations();
  return m;
}

// An element's strain is resolved to eps |x| / l of its nodes' positions: relative to the strain,
// about 1e-8 here, so the tension cannot be closer than that.
const double kTensionPrecision = 5.0 * std::numeric_limits<double>::epsilon() *
                                 (kOffset + kLength) / (kLength / kElements) / kStretch;

// Axial force of the uniformly stretched cable: S A0 lambda with S = E (lambda^2 - 1) / 2
// (Eq. 2.53).
double exactTension() {
  const double lambda = 1.0 + kStretch;
  return kE * (lambda * lambda - 1.0) / 2.0 * kArea * lambda;
}

TEST(RoundOffFloor, StiffFineChainConvergesAtItsFloorWithTheExactTension) {
  const auto m = stiffChain();
  const model::Assembler assembler(*m);
  model::State state = m->initialState();
  solve::StaticOptions o;  // default: Eq. 5.1 at 1e-6 and the residual at 1e-8, both
  o.convergence.displacement_tolerance = 1e-10;
  ASSERT_NO_THROW(solve::solveStatic(assembler, state, o));

  model::SparseMatrix K;
  const solve::Residual R = solve::outOfBalance(assembler, state, &K);
  RecordProperty("floor", std::to_string(R.floor));
  RecordProperty("residual", std::to_string(R.relative()));
  EXPECT_GT(R.floor, o.convergence.residual_tolerance);  // the plain tolerance is out of reach
  EXPECT_LT(R.relative(), R.floor);
  for (int e : {0, kElements / 2, kElements - 1})
    EXPECT_NEAR(assembler.elementResults(state)[e].end_tension[0] / exactTension(), 1.0,
                kTensionPrecision);
}

TEST(RoundOffFloor, TimeStepsOfTheStiffChainConverge) {
  const auto m = stiffChain();
  const model::Assembler assembler(*m);
  model::State state = m->initialState();
  solve::solveStatic(assembler, state, {});
  // Released from a sag of 0.1 m (y) and 0.5 m (z) at mid-span.
  for (int i = 1; i < kElements; ++i) {
    const double s = static_cast<double>(i) / kElements;
    state.displacement(1, i) = 0.4 * s * (1.0 - s);
    state.displacement(2, i) = -2.0 * s * (1.0 - s);
  }
  solve::DynamicOptions o;
  o.schedule = {{1e-3, 3}};
  o.convergence.use_displacement = false;  // the residual alone: the hardest case
  o.max_step_cuts = 0;
  solve::DynamicReport report;
  ASSERT_NO_THROW(report = solve::integrate(assembler, state, o));
  EXPECT_EQ(report.steps, 3);
}

}  // namespace
}  // namespace flexmoor
