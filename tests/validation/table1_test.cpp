// Validation against Table 1 of the dissertation (Chapter V, Example 1: a suspended cable found by
// viscous relaxation). Reference: seed-tables.csv, docs/theory.md#example-1, centre sag dC and support
// movement dR in ft:
//   8 linear elements     58.13 / 47.68
//   4 quadratic elements  59.25 / 46.93
//   2 cubic elements      57.84 / 46.89
//   "true solution"       57.80 / 47.92
// The span and the roller force were in a lost figure; L0 = 200 ft and H = 5.8 lbf are the
// reconstruction (docs/theory.md#example-1). E, A, rho, g and the relaxation parameters (tolerance 0.001,
// C = 10,000, initial damping factor 0.01, decrement 1.00) are the dissertation's.
//
// The models are the dissertation's: straight, equally spaced nodes, default quadrature (as many
// Gauss points as nodes), and an element that carries compression (Compression::Carry): the
// dissertation's linear-elastic element is a bar. A tension-only law changes the 4 x L3 answer
// (sag by 1.3%), because interior Gauss points of the curved quadratic elements are in
// compression: a quadratic element cannot keep its stretch uniform when it curves, and in this
// stiff cable (EA / T ~ 1e4) the spurious strains show up as forces of tens of lbf, down to about
// -40 lbf where the true tension is 5.8 to 11.6 lbf. A tension-only law lets them go slack.
//
// Tolerance: 1.5% of the published value for each figure (the reconstruction of the lost inputs
// and the published figures' rounding both sit well inside it; the published "true solution"
// itself differs by 0.3-0.5% from the elastic catenary of the reconstructed inputs).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "tests/support/cable_models.hpp"
#include "tests/support/elastic_catenary.hpp"

namespace flexmoor::test {
namespace {

struct PublishedModel {
  const char* name;
  int elements;
  int nodes_per_element;
  double centre_sag;        // ft, Table 1
  double support_movement;  // ft, Table 1
};

constexpr PublishedModel kEightLinear{"8 linear", 8, 2, 58.13, 47.68};
constexpr PublishedModel kFourQuadratic{"4 quadratic", 4, 3, 59.25, 46.93};
constexpr PublishedModel kTwoCubic{"2 cubic", 2, 4, 57.84, 46.89};

// Runs the model and checks both figures against Table 1 within `tolerance` (relative).
void expectTable1(const PublishedModel& published, material::Compression compression,
                  double tolerance) {
  const SuspendedCable cable = makeSuspendedCable(SuspendedCableInputs{}, published.elements,
                                                  published.nodes_per_element, compression);
  const SagAndMovement fe = relaxSuspendedCable(cable);
  const double sag_error = (fe.centre_sag - published.centre_sag) / published.centre_sag;
  const double movement_error =
      (fe.support_movement - published.support_movement) / published.support_movement;
  std::cout << "[ Table 1, " << published.name
            << (compression == material::Compression::Carry ? "" : ", tension only") << " ] sag "
            << fe.centre_sag << " ft (published " << published.centre_sag << ", "
            << 100.0 * sag_error << " %), movement " << fe.support_movement << " ft (published "
            << published.support_movement << ", " << 100.0 * movement_error << " %), "
            << fe.report.steps << " relaxation steps\n";
  ::testing::Test::RecordProperty("centre_sag_error_percent", std::to_string(100.0 * sag_error));
  ::testing::Test::RecordProperty("support_movement_error_percent",
                                  std::to_string(100.0 * movement_error));
  EXPECT_LT(std::abs(sag_error), tolerance);
  EXPECT_LT(std::abs(movement_error), tolerance);
}

// Table 1, 8 linear elements: 58.13 / 47.68 ft, within 1.5%.
TEST(Table1, EightLinearElements) {
  expectTable1(kEightLinear, material::Compression::Carry, 0.015);
}

// Table 1, 4 quadratic elements: 59.25 / 46.93 ft, within 1.5%.
TEST(Table1, FourQuadraticElements) {
  expectTable1(kFourQuadratic, material::Compression::Carry, 0.015);
}

// Table 1, 2 cubic elements: 57.84 / 46.89 ft, within 1.5%.
TEST(Table1, TwoCubicElements) { expectTable1(kTwoCubic, material::Compression::Carry, 0.015); }

// With a tension-only law the slack interior Gauss points of the 4 x L3 model soften it; the
// answer must still lie within 2.5% of Table 1. The compression-carrying model must really have
// a Gauss point in compression (the true tension is >= H = 5.8 lbf everywhere), the tension-only
// one none, and their answers must differ by more than 0.1%.
TEST(Table1, FourQuadraticElementsTensionOnly) {
  expectTable1(kFourQuadratic, material::Compression::TensionOnly, 0.025);
  const SuspendedCableInputs inputs;
  const SagAndMovement carry =
      relaxSuspendedCable(makeSuspendedCable(inputs, 4, 3, material::Compression::Carry));
  const SagAndMovement slack =
      relaxSuspendedCable(makeSuspendedCable(inputs, 4, 3, material::Compression::TensionOnly));
  std::cout << "[ 4 x L3 ] least Gauss-point tension: carry " << carry.least_point_tension
            << " lbf, tension only " << slack.least_point_tension << " lbf\n";
  EXPECT_LT(carry.least_point_tension, 0.0);
  EXPECT_GE(slack.least_point_tension, 0.0);
  EXPECT_GT(std::abs(slack.centre_sag - carry.centre_sag), 1e-3 * carry.centre_sag);
}

// The published "true solution" is itself an elastic catenary: the pair 57.80 / 47.92 ft is that
// of L0 = 200.38 ft, H = 5.795 lbf (docs/theory.md#example-1), not of the reconstructed 200 ft / 5.8 lbf.
// Reference: the analytic catenary (law (b)); tolerance 0.01 ft, the published rounding (0.005 ft)
// plus that of the back-solved inputs.
TEST(Table1, PublishedTrueSolutionIsAnElasticCatenary) {
  CatenaryInputs in = SuspendedCableInputs{}.catenary();
  in.unstretched_length = 200.38;
  in.horizontal_force = 5.795;
  const CatenaryShape c = greenStrainCatenary(in);
  EXPECT_NEAR(c.centre_sag, 57.80, 0.01);
  EXPECT_NEAR(c.support_movement, 47.92, 0.01);
}

}  // namespace
}  // namespace flexmoor::test
