// Validation against Table 4 of the dissertation (Chapter V, Example 6: natural frequencies of a
// pretensioned taut cable), through the command: `flexmoor run ex6-cable-modes-...` and its
// summary.json (omega_1 .. omega_10, rad/s), compared with the rows of
// data/reference/seed-tables.csv read at test time.
//
// Models: 12 linear (12xL2), 6 quadratic (6xL3), 4 cubic (4xL4) elements, equally spaced nodes,
// consistent mass, plane problem (y fixed). Exact solution omega_n = n pi / L sqrt(T / m)
// = n * 9.5596 rad/s. The inputs of the lost Fig. 20 are reconstructed so that this holds in the
// pretensioned state (see the header of cases/seed/ex6-cable-modes-12xL2.yaml).
//
// Three checks per model:
//  1. Table 4, every printed entry within 0.1% relative (the printed figures carry 5 significant
//     digits and agree with the consistent-mass models to 5e-5; the reconstruction is exact to
//     1e-6), except two entries that contradict the rest of their own row (below), which are
//     checked against the independent value instead.
//  2. The whole spectrum against an independent solve written here: the string's stiffness and
//     consistent mass assembled from Lagrange polynomials on equally spaced nodes (exact Gauss
//     integration) and reduced with Eigen's dense generalized eigensolver - no flexmoor element
//     or solver code. Tolerance 1e-6 relative (the density in the case file has 8 digits).
//  3. The exact continuum (Table 4's exact row): every FE frequency is an upper bound (Rayleigh-
//     Ritz with consistent mass), and the fundamental is within 0.5%. The tolerance is loose
//     because it measures discretisation error, not the implementation: the coarse models miss
//     the higher modes by up to 33% (4 cubic, mode 10), and the fundamental of 12 linear elements
//     by 0.28% (about (pi / 12)^2 / 24).
//
// Inconsistent entries of Table 4, excluded from check 1 (not by loosening the tolerance):
//  - "6 quadratic", mode 7, printed 73.735. The consistent-mass 6xL3 string gives 73.347 (check 2
//    and flexmoor agree to 1e-8); the row's other nine entries agree with it to 5e-5. 73.735
//    repeats the decimals ".735" of its neighbour, mode 6 (57.735): a copying slip.
//  - "4 cubic", mode 10, printed 127.570. The consistent-mass 4xL4 string gives 127.158; modes
//    1-9 agree to 5e-5. Either a misprint or the unconverged Ritz value of the last requested
//    mode of the dissertation's subspace iteration (the slowest to converge, and approached from
//    above, as 127.570 > 127.158 is).
// For each, the test also confirms that the printed figure really is more than 0.1% off, so the
// exclusion fails loudly, instead of skipping a good entry, if the transcription is corrected.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "tests/support/cli_run.hpp"
#include "tests/support/seed_tables.hpp"

namespace {

using flexmoor::test::runNamedCase;
using flexmoor::test::summaryValue;
using flexmoor::test::tableRow;
// Independent reference: fixed-fixed string of unit length, T / m = 1 / pi^2 (so the exact
// omega_n = n), `elements` Lagrange elements of `nodes` equally spaced nodes, consistent mass.

// Gauss-Legendre points and weights on [-1, 1] (Newton on the Legendre polynomial).
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(M_PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k)
        std::tie(p0, p1) = std::pair(p1, ((2 * k - 1) * t * p1 - (k - 1) * p0) / k);
      dp = n * (t * p1 - p0) / (t * t - 1.0);
      const double step = p1 / dp;
      t -= step;
      if (std::abs(step) < 1e-16) break;
    }
    x[i] = t;
    w[i] = 2.0 / ((1.0 - t * t) * dp * dp);
  }
}

// Lagrange polynomials on equally spaced nodes of [-1, 1] and their derivatives at xi.
void lagrange(int nodes, double xi, std::vector<double>& N, std::vector<double>& dN) {
  N.assign(nodes, 1.0);
  dN.assign(nodes, 0.0);
  const auto node = [nodes](int i) { return -1.0 + 2.0 * i / (nodes - 1); };
  for (int i = 0; i < nodes; ++i)
    for (int j = 0; j < nodes; ++j) {
      if (j == i) continue;
      N[i] *= (xi - node(j)) / (node(i) - node(j));
      double term = 1.0 / (node(i) - node(j));
      for (int k = 0; k < nodes; ++k)
        if (k != i && k != j) term *= (xi - node(k)) / (node(i) - node(k));
      dN[i] += term;
    }
}

// omega_k / omega_1,exact of the discrete string, ascending, k = 1 .. interior nodes.
std::vector<double> discreteStringRatios(int elements, int nodes) {
  const int count = elements * (nodes - 1) + 1;
  const double h = 1.0 / elements, tension = 1.0 / (M_PI * M_PI), mass = 1.0;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(count, count), M = K;
  std::vector<double> x, w, N, dN;
  gaussLegendre(nodes + 1, x, w);  // exact for the mass, degree 2 (nodes - 1)
  for (int e = 0; e < elements; ++e)
    for (size_t g = 0; g < x.size(); ++g) {
      lagrange(nodes, x[g], N, dN);
      const double jacobian = h / 2.0;
      for (int a = 0; a < nodes; ++a)
        for (int b = 0; b < nodes; ++b) {
          const int i = e * (nodes - 1) + a, j = e * (nodes - 1) + b;
          K(i, j) += tension * dN[a] * dN[b] / jacobian * w[g];
          M(i, j) += mass * N[a] * N[b] * jacobian * w[g];
        }
    }
  const int interior = count - 2;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      K.block(1, 1, interior, interior), M.block(1, 1, interior, interior));
  std::vector<double> ratios;
  for (int k = 0; k < interior; ++k) ratios.push_back(std::sqrt(solver.eigenvalues()(k)));
  return ratios;
}

// ---------------------------------------------------------------------------------------------

struct Table4Case {
  const char* case_name;
  const char* model;  // the model column of seed-tables.csv
  int elements;
  int nodes_per_element;
  int misprinted_mode;  // the entry of the row that contradicts the rest (0: none)
};
void PrintTo(const Table4Case& c, std::ostream* os) {
  *os << c.case_name << " (" << c.model << ")";
}

// Table 4's exact row gives omega_1 = 9.5596 rad/s most precisely in its mode 10 (95.596).
double exactFundamental() { return tableRow("table4", "exact").at(10) / 10.0; }

class Example6 : public ::testing::TestWithParam<Table4Case> {};

// Check 1: every entry of the model's row of Table 4 within 0.1%, the misprinted one excepted.
TEST_P(Example6, ReproducesTable4Within0_1Percent) {
  const Table4Case c = GetParam();
  const std::map<int, double> published = tableRow("table4", c.model);
  ASSERT_EQ(published.size(), 10u) << c.model;
  const std::string json = runNamedCase(c.case_name);
  const std::vector<double> independent = discreteStringRatios(c.elements, c.nodes_per_element);
  double worst = 0.0;
  for (const auto& [mode, value] : published) {
    const double omega = summaryValue(json, "omega_" + std::to_string(mode));
    ASSERT_FALSE(std::isnan(omega)) << "omega_" << mode << " missing\n" << json;
    const double error = omega / value - 1.0;
    if (mode == c.misprinted_mode) {
      // Checked against the independent consistent-mass solve instead; the printed figure must
      // really be off, or the exclusion would have no reason.
      const double trusted = independent[mode - 1] * exactFundamental();
      std::cout << "[ Table 4, " << c.model << " ] mode " << mode << ": printed " << value
                << " excluded (misprint); measured " << omega << ", independent " << trusted
                << " (printed is " << 100.0 * (value / trusted - 1.0) << " % off)\n";
      EXPECT_NEAR(omega / trusted, 1.0, 1e-6) << "mode " << mode;
      EXPECT_GT(std::abs(value / trusted - 1.0), 1e-3) << "mode " << mode;
      continue;
    }
    worst = std::max(worst, std::abs(error));
    EXPECT_LT(std::abs(error), 1e-3) << "mode " << mode << ": " << omega << " vs " << value;
  }
  std::cout << "[ Table 4, " << c.model << " ] largest relative error vs the table " << worst
            << "\n";
  ::testing::Test::RecordProperty("max_relative_error_vs_table", std::to_string(worst));
}

// Check 2: omega_1 .. omega_10 against the independent solve of the same discrete string.
TEST_P(Example6, MatchesIndependentConsistentMassSolve) {
  const Table4Case c = GetParam();
  const std::string json = runNamedCase(c.case_name);
  const std::vector<double> independent = discreteStringRatios(c.elements, c.nodes_per_element);
  ASSERT_EQ(independent.size(), 11u);
  const double omega1 = exactFundamental();
  double worst = 0.0;
  for (int mode = 1; mode <= 10; ++mode) {
    const double omega = summaryValue(json, "omega_" + std::to_string(mode));
    const double error = omega / (independent[mode - 1] * omega1) - 1.0;
    worst = std::max(worst, std::abs(error));
    EXPECT_LT(std::abs(error), 1e-6) << "mode " << mode << ": " << omega;
  }
  std::cout << "[ Table 4, " << c.model << " ] largest relative difference from the independent "
            << "solve " << worst << "\n";
  ::testing::Test::RecordProperty("max_relative_error_vs_independent", std::to_string(worst));
}

// Check 3: the exact continuum (Table 4's exact row): upper bounds, and the fundamental within
// 0.5%. The allowance 1e-4 below the exact figure covers its printing (86.040 for mode 9 is
// 9 x 9.5596 = 86.036 rounded up; the rest are n x 9.5596 to 1e-5).
TEST_P(Example6, ConvergesFromAboveToTheExactString) {
  const Table4Case c = GetParam();
  const std::map<int, double> exact = tableRow("table4", "exact");
  ASSERT_EQ(exact.size(), 10u);
  const std::string json = runNamedCase(c.case_name);
  std::ostringstream errors;
  for (const auto& [mode, value] : exact) {
    const double omega = summaryValue(json, "omega_" + std::to_string(mode));
    EXPECT_GT(omega, value * (1.0 - 1e-4)) << "mode " << mode << " below the exact " << value;
    errors << " " << 100.0 * (omega / value - 1.0);
  }
  const double fundamental = summaryValue(json, "omega_1") / exact.at(1) - 1.0;
  std::cout << "[ Table 4, " << c.model << " ] error vs exact, %:" << errors.str() << "\n";
  ::testing::Test::RecordProperty("fundamental_error_vs_exact", std::to_string(fundamental));
  EXPECT_LT(std::abs(fundamental), 5e-3);
}

INSTANTIATE_TEST_SUITE_P(
    Table4, Example6,
    ::testing::Values(Table4Case{"ex6-cable-modes-12xL2", "12 linear", 12, 2, 0},
                      Table4Case{"ex6-cable-modes-6xL3", "6 quadratic", 6, 3, 7},
                      Table4Case{"ex6-cable-modes-4xL4", "4 cubic", 4, 4, 10}),
    flexmoor::test::CaseParamName());

}  // namespace
