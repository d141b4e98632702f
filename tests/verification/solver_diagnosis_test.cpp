// What the solvers say when they cannot go on, for structures a case file's checks would refuse
// (so built in code): a mechanism under load in a static and a relaxation step, and a frequency
// analysis with a free dof that has no mass. Each message names the cause and the dof; numbers in
// %g style.
#include <gtest/gtest.h>

#include <string>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/modal.hpp"
#include "libstruct/solve/static_solver.hpp"
#include "libstruct/solve/viscous_relaxation.hpp"
#include "tests/support/cable_models.hpp"

namespace flexmoor::test {
namespace {

// A 10 m steel wire of 4 linear elements along x, with every y fixed and nothing else: pulled at
// its end (node 2) by 10 N in x, nothing balances the load. density: 0 for the massless variant.
std::unique_ptr<model::Model> unsupportedWire(double density) {
  auto m = std::make_unique<model::Model>();
  const int a = m->addNode(Eigen::Vector3d::Zero());
  const int b = m->addNode(Eigen::Vector3d(10.0, 0.0, 0.0));
  const std::vector<int> nodes = addStraightCable(
      *m, a, b, 4, 2, linearElasticSection(2.0e11, 1.0e-4, density, material::Compression::Carry));
  for (int n : nodes) m->constrain(n, 1);
  m->addNodalLoad(b, Eigen::Vector3d(10.0, 0.0, 0.0));
  return m;
}

std::string failure(const std::function<void()>& run) {
  try {
    run();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no failure)";
}

void expectFragments(const std::string& message, const std::vector<std::string>& fragments) {
  for (const std::string& f : fragments)
    EXPECT_NE(message.find(f), std::string::npos) << "missing '" << f << "' in\n" << message;
  EXPECT_EQ(message.find("000000"), std::string::npos) << message;
}

// Static: the singular tangent is regularised and the solve pushes the wire off to 1e10 m. That
// would pass as an equilibrium (residual 0.75, under a round-off floor of about 5 at such
// coordinates) if the floor were not capped at 1e-4.
TEST(SolverDiagnosis, StaticMechanismUnderLoadIsNamed) {
  const auto m = unsupportedWire(7850.0);
  m->numberEquations();
  const model::Assembler assembler(*m);
  model::State state = m->initialState();
  const std::string message = failure([&] { solve::solveStatic(assembler, state, {}); });
  expectFragments(message, {"did not converge", "the tangent was singular: a mechanism",
                            "the largest displacement increment of the last iteration"});
}

// Relaxation: the message names the mechanism and where it moves. The wire falls further with
// every pseudo-time step, as the damping falls; at step 35 the step's Newton iterations stall (a
// residual of 6e-4 of the forces, increments of 3e-10) however much the damping is raised, and the
// step fails with the mechanism named.
TEST(SolverDiagnosis, RelaxationOfAMechanismUnderLoadIsNamed) {
  const auto m = unsupportedWire(7850.0);
  m->numberEquations();
  const model::Assembler assembler(*m);
  model::State state = m->initialState();
  solve::RelaxationOptions o;
  o.max_steps = 50;
  const std::string message = failure([&] { solve::relax(assembler, state, o); });
  expectFragments(message, {"viscous relaxation step", "did not converge even with damping",
                            "the motion is one no stiffness holds: a mechanism", "at node"});
}

// Modes without mass: the dof is named, not only "the mass matrix is not positive definite". The wire
// is pinned at its start (node 1) and its end (node 2, added second) rides on a roller along x:
// its x is the first free dof, named with the default names (1-based model nodes).
TEST(SolverDiagnosis, ModesOfAMasslessDofNameIt) {
  const auto m = unsupportedWire(0.0);
  for (int k = 0; k < 3; ++k) m->constrain(0, k);
  m->constrain(1, 2);
  m->numberEquations();
  const model::Assembler assembler(*m);
  model::State state = m->initialState();
  state.load_factor = 1.0;
  solve::ModalOptions o;
  o.modes = 1;
  const std::string message = failure([&] { solve::naturalModes(assembler, state, o); });
  expectFragments(message, {"the mass matrix is not positive definite: node 2 x has no mass"});
}

}  // namespace
}  // namespace flexmoor::test
