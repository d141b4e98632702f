// Verification of the frequency analysis (solve/modal.cpp: K_T phi = omega^2 M phi about the
// current state; dense below 200 equations, shift-invert Lanczos above).
//
// Reference: a taut straight cable of n consistent-mass linear (two-node) elements. With a
// uniform stretch lambda, second Piola stress S = E (lambda^2 - 1) / 2 and reference element
// length h0, each element's transverse stiffness is the geometric one, S A0 / h0 = N / h, and its
// axial stiffness (E lambda^2 + S) A0 / h0 = (dN / d lambda) / h0; its mass rho0 A0 h0 / 6
// [2 1; 1 2]. The discrete string with fixed ends then has the closed-form frequencies
//   omega_k^2 = (6 c / (rho0 h0^2)) (1 - cos(k pi / n)) / (2 + cos(k pi / n)),  k = 1 .. n - 1,
// with c = S (transverse) or c = E lambda^2 + S (axial); for the transverse ones this is
// 6 T / (m h^2) (...) in the stretched tension T, mass per stretched length m and stretched h.
#include "libstruct/solve/modal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

#include "libstruct/model/assembler.hpp"
#include "libstruct/solve/equilibrium.hpp"
#include "tests/support/dynamic_models.hpp"

namespace flexmoor::test {
namespace {

solve::ModalResult allModes(const model::Assembler& assembler, const model::State& state,
                            element::MassKind mass = element::MassKind::Consistent) {
  solve::ModalOptions o;
  o.modes = assembler.equationCount();
  o.mass = mass;
  return solve::naturalModes(assembler, state, o);
}

// Largest relative deviation of the frequencies of `modes` (indices into r) from the closed form
// of the string, mode k = 1, 2, ... in the order given, each k repeated `multiplicity` times.
double closedFormError(const solve::ModalResult& r, const std::vector<int>& modes, int multiplicity,
                       int elements, double modulus, const TautCableInputs& in) {
  double worst = 0.0;
  for (size_t i = 0; i < modes.size(); ++i) {
    const int k = static_cast<int>(i) / multiplicity + 1;
    const double exact =
        linearStringFrequency(elements, k, modulus * in.area, in.density * in.area, in.length);
    worst = std::max(worst, std::abs(r.omega[modes[i]] / exact - 1.0));
  }
  return worst;
}

// Plane taut string (y fixed), 12 L2 elements, right end pulled to stretch 1.001 by a prescribed
// displacement. Every one of the 11 transverse (z) and 11 axial (x) frequencies against the
// closed form (in reference quantities: T / (m h^2) = S / (rho0 h0^2)). Tolerance 1e-8 relative
// (the dense solver's error is ~1e-16 of the largest eigenvalue, ~1e-11 of the smallest here).
// The pretensioned state itself is the uniform stretch to 1e-12.
TEST(Modal, TautStringMatchesConsistentMassClosedForm) {
  TautCableInputs in;
  in.planar = true;
  const TautCable cable = makeTautCable(in);
  const model::Assembler assembler(*cable.model);
  const model::State state = pretension(cable, assembler);
  for (int n : cable.nodes)
    EXPECT_NEAR(state.displacement(0, n), (in.stretch - 1.0) * cable.model->reference()(0, n),
                1e-12 * in.length);

  const solve::ModalResult r = allModes(assembler, state);
  const std::vector<int> transverse = modesAlong(r, {2});
  const std::vector<int> axial = modesAlong(r, {0});
  ASSERT_EQ(transverse.size(), 11u);
  ASSERT_EQ(axial.size(), 11u);
  const double transverse_error =
      closedFormError(r, transverse, 1, in.elements, in.secondPiola(), in);
  const double axial_error = closedFormError(r, axial, 1, in.elements, in.axialModulus(), in);
  // The same closed form written in the stretched quantities T, m, L.
  const double first =
      linearStringFrequency(in.elements, 1, in.tension(), in.massPerLength(), in.stretchedLength());
  std::cout << std::setprecision(12)
            << "[ Modal, taut string 12 x L2 ] omega_1 = " << r.omega[transverse[0]]
            << " (closed form " << first << "); largest rel. error: transverse " << transverse_error
            << ", axial " << axial_error << "\n";
  EXPECT_NEAR(r.omega[transverse[0]] / first, 1.0, 1e-8);
  EXPECT_LT(transverse_error, 1e-8);
  EXPECT_LT(axial_error, 1e-8);
}

// Lumped mass (half of each element's mass at each end node) turns the string into the classic
// finite-difference chain: omega_k = (2 / h0) sqrt(S / rho) sin(k pi / (2 n)) in reference
// quantities (S the second Piola stress, h0 = L0 / n); it lies below the exact string, where the
// consistent mass lies above.
TEST(Modal, TautStringWithLumpedMassMatchesFiniteDifferenceClosedForm) {
  TautCableInputs in;
  in.planar = true;
  const TautCable cable = makeTautCable(in);
  const model::Assembler assembler(*cable.model);
  const model::State state = pretension(cable, assembler);
  const solve::ModalResult lumped = allModes(assembler, state, element::MassKind::Lumped);
  const solve::ModalResult consistent = allModes(assembler, state);
  const std::vector<int> transverse = modesAlong(lumped, {2});
  const std::vector<int> transverse_consistent = modesAlong(consistent, {2});
  ASSERT_EQ(transverse.size(), 11u);
  const double h0 = in.length / in.elements;
  double worst = 0.0;
  for (size_t i = 0; i < transverse.size(); ++i) {
    const int k = static_cast<int>(i) + 1;
    const double expected = 2.0 / h0 * std::sqrt(in.secondPiola() / in.density) *
                            std::sin(k * M_PI / (2.0 * in.elements));
    worst = std::max(worst, std::abs(lumped.omega[transverse[i]] / expected - 1.0));
    const double exact = k * M_PI / in.length * std::sqrt(in.secondPiola() / in.density);
    EXPECT_LT(lumped.omega[transverse[i]], exact) << "mode " << k;
    EXPECT_GT(consistent.omega[transverse_consistent[i]], exact) << "mode " << k;
  }
  EXPECT_LT(worst, 1e-8);
}

// Mass orthonormality of the returned shapes, phi_i^T M phi_j = delta_ij to 1e-8, on the 3-D
// taut cable, whose transverse modes come in equal (y, z) pairs (the solver must return an
// orthonormal basis of each pair); and phi_i^T K phi_j = omega_i^2 delta_ij to 1e-8 of omega_max^2.
TEST(Modal, ModeShapesAreMassOrthonormal) {
  const TautCable cable = makeTautCable(TautCableInputs{});
  const model::Assembler assembler(*cable.model);
  const model::State state = pretension(cable, assembler);
  solve::ModalOptions o;
  o.modes = 20;
  const solve::ModalResult r = solve::naturalModes(assembler, state, o);
  ASSERT_EQ(r.shapes.size(), 20u);
  model::SparseMatrix M, K;
  Eigen::VectorXd F;
  assembler.mass(state, element::MassKind::Consistent, M);
  assembler.internalForce(state, F, &K);
  Eigen::MatrixXd Phi(assembler.equationCount(), 20);
  for (int i = 0; i < 20; ++i) Phi.col(i) = assembler.restrictToFree(solve::asVector(r.shapes[i]));
  const Eigen::MatrixXd mass_error = Phi.transpose() * M * Phi - Eigen::MatrixXd::Identity(20, 20);
  Eigen::MatrixXd stiffness_error = Phi.transpose() * K * Phi;
  for (int i = 0; i < 20; ++i) stiffness_error(i, i) -= r.omega[i] * r.omega[i];
  const double omega_max = r.omega.back();
  std::cout << "[ Modal, orthonormality ] max |Phi^T M Phi - I| = "
            << mass_error.cwiseAbs().maxCoeff() << ", max |Phi^T K Phi - Omega^2| / omega_max^2 = "
            << stiffness_error.cwiseAbs().maxCoeff() / (omega_max * omega_max) << "\n";
  EXPECT_LT(mass_error.cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LT(stiffness_error.cwiseAbs().maxCoeff(), 1e-8 * omega_max * omega_max);
}

// The sign convention: an eigenvector's sign is arbitrary (round-off flips it between builds),
// so each shape comes with its component of largest magnitude positive, on the dense path (20
// modes of 57 equations) and on the sparse one (5 of 447). Checked exactly: the largest entry
// is > 0 and no entry is below -(largest).
TEST(Modal, EachModeShapesLargestComponentIsPositive) {
  for (const int elements : {20, 150}) {
    TautCableInputs in;
    in.elements = elements;
    const TautCable cable = makeTautCable(in);
    const model::Assembler assembler(*cable.model);
    const model::State state = pretension(cable, assembler);
    solve::ModalOptions o;
    o.modes = elements == 20 ? 20 : 5;
    const solve::ModalResult r = solve::naturalModes(assembler, state, o);
    for (const model::NodalField& shape : r.shapes) {
      EXPECT_GT(shape.maxCoeff(), 0.0) << elements << " elements";
      EXPECT_GE(shape.minCoeff(), -shape.maxCoeff()) << elements << " elements";
    }
  }
}

// The sparse (Lanczos) path: a 3-D taut cable of 150 L2 elements (447 equations, more than the
// dense limit of 200), stretch 1.01. Ten modes by Lanczos against the same ten from the dense
// path (asking for half the equations selects it) and against the closed form: the five lowest
// transverse frequencies, each twice (y and z). Tolerance 1e-8 relative.
TEST(Modal, SparsePathMatchesDensePathAndClosedForm) {
  TautCableInputs in;
  in.elements = 150;
  in.stretch = 1.01;
  const TautCable cable = makeTautCable(in);
  const model::Assembler assembler(*cable.model);
  ASSERT_GT(assembler.equationCount(), 200);
  const model::State state = pretension(cable, assembler);
  solve::ModalOptions o;
  o.modes = 10;
  const solve::ModalResult sparse = solve::naturalModes(assembler, state, o);
  o.modes = assembler.equationCount() / 2 + 1;
  const solve::ModalResult dense = solve::naturalModes(assembler, state, o);
  ASSERT_EQ(sparse.omega.size(), 10u);
  std::vector<int> first_ten(10);
  for (int i = 0; i < 10; ++i) first_ten[i] = i;
  double sparse_vs_dense = 0.0;
  for (int i = 0; i < 10; ++i)
    sparse_vs_dense = std::max(sparse_vs_dense, std::abs(sparse.omega[i] / dense.omega[i] - 1.0));
  const double sparse_error =
      closedFormError(sparse, first_ten, 2, in.elements, in.secondPiola(), in);
  const double dense_error =
      closedFormError(dense, first_ten, 2, in.elements, in.secondPiola(), in);
  std::cout << std::setprecision(12) << "[ Modal, 150 x L2 sparse path ] omega:";
  for (double w : sparse.omega) std::cout << ' ' << w;
  std::cout << "\n  largest rel. diff: sparse vs dense " << sparse_vs_dense
            << ", sparse vs closed form " << sparse_error << ", dense vs closed form "
            << dense_error << "\n";
  EXPECT_LT(sparse_vs_dense, 1e-8);
  EXPECT_LT(sparse_error, 1e-8);
  EXPECT_LT(dense_error, 1e-8);
  EXPECT_EQ(modesAlong(sparse, {1, 2}).size(), 10u);  // all transverse
}

// A free-floating rigid truss (no support): six rigid-body modes of zero frequency come first.
// Dense path: one cubic cell (8 nodes, 24 equations); sparse path: 5 x 5 x 5 nodes
// (375 equations). Zero means omega < 1e-6 omega_7 (round-off gives ~1e-8 of omega_max); the
// seventh must be a true elastic mode.
void expectSixRigidBodyModes(int n, const char* label) {
  const auto truss = makeFreeTruss(n, n, n);
  const model::Assembler assembler(*truss);
  const model::State state = truss->initialState();
  solve::ModalOptions o;
  o.modes = 10;
  const solve::ModalResult r = solve::naturalModes(assembler, state, o);
  ASSERT_EQ(r.omega.size(), 10u);
  std::cout << "[ Modal, free truss " << label << ", " << assembler.equationCount()
            << " equations ] omega:";
  for (double w : r.omega) std::cout << ' ' << w;
  std::cout << "\n";
  for (int i = 0; i < 6; ++i) EXPECT_LT(r.omega[i], 1e-6 * r.omega[6]) << "mode " << i + 1;
  EXPECT_GT(r.omega[6], 0.0);
}

TEST(Modal, FreeFloatingTrussHasSixZeroFrequenciesFirstDense) {
  expectSixRigidBodyModes(2, "dense");
}

TEST(Modal, FreeFloatingTrussHasSixZeroFrequenciesFirstSparse) {
  expectSixRigidBodyModes(5, "sparse");
}

}  // namespace
}  // namespace flexmoor::test
