// Validation against Table 5 of the dissertation (Chapter V, Example 7: natural frequencies of a
// square membrane under uniform tension), through the command: `flexmoor run
// ex7-membrane-modes-...` and its summary.json (omega_1 .. omega_8, rad/s; omega_1 .. omega_5 for
// 4 Q8, which has only 5 transverse dofs), compared with the rows of
// data/reference/seed-tables.csv read at test time.
//
// Models (Fig. 23): 9 Q8 (3x3), 4 Q12 (2x2), 4 Q8 (2x2), 25 Q4 (5x5), 16 Q4 (4x4), 8 T6 (2x2
// squares, diagonals meeting at the centre), the full square with its edges held, consistent
// mass. Exact omega_mn = pi sqrt(N / (rho h)) sqrt(m^2 + n^2) / a, omega_11 = pi sqrt(500/3)
// = 40.558 rad/s for the reconstructed inputs of the lost Fig. 22 (see the header of
// cases/seed/ex7-membrane-modes-16xQ4.yaml).
//
// Checks per model:
//  1. Table 5, every printed entry within 0.1% relative. No entry of Table 5 is excluded: all 45
//     agree with the flexmoor models to 3e-4 or better (the printed figures carry 4 or 5
//     significant digits, about 1e-4, so the 0.1% tolerance is the requirement, not a fit). The
//     largest difference, 25 Q4 modes 7/8 printed 115.80 against 115.832 (2.8e-4; the
//     consistent-mass closed form of check 3 gives 115.832 too), is the dissertation's own:
//     Table 6 prints 11.99% for it, which is 115.80 / 103.40.
//  2. The exact continuum (Table 5's exact row): every FE frequency is an upper bound of the exact
//     one of the same rank (Rayleigh-Ritz: conforming elements, consistent mass, exact
//     integration), the (1,2)/(2,1) pair is degenerate (omega_2 = omega_3, to 1e-8; every mesh is
//     symmetric about the diagonal x = y), and the fundamental is within 4%. That tolerance is
//     loose because it measures discretisation error: the coarsest model's fundamental (8 T6) is
//     3.4% high, as Table 6 also reports.
//  3. The Q4 models against the closed form of their own discrete spectrum: with consistent mass
//     and 2x2 Gauss points the bilinear stiffness and mass are Kronecker sums/products of the 1-D
//     linear-element matrices, so omega_ij^2 = (N / (rho h)) (mu_i + mu_j) with
//     mu_k = 6 / h^2 (1 - cos(k pi / n)) / (2 + cos(k pi / n)). The ratios omega_k / omega_1 to
//     1e-8; the scale to 1e-4 against omega_11 fitted to the exact row's modes 2-8 (Table 5
//     prints the exact omega_11 as 40.55, one digit below pi sqrt(500/3) = 40.558, to which its
//     other seven entries point).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "tests/support/cli_run.hpp"
#include "tests/support/seed_tables.hpp"

namespace {

using flexmoor::test::runNamedCase;
using flexmoor::test::summaryValue;
using flexmoor::test::tableRow;

struct Table5Case {
  const char* case_name;
  const char* model;  // the model column of seed-tables.csv
  int q4_divisions;   // n of an n x n Q4 mesh (check 3); 0 for the other elements
};
void PrintTo(const Table5Case& c, std::ostream* os) {
  *os << c.case_name << " (" << c.model << ")";
}

// (m^2 + n^2) / 2 of the exact modes in Table 5's order: (1,1), (1,2) twice, (2,2), (1,3) twice,
// (2,3) twice.
constexpr double kExactShape[] = {1.0, 2.5, 2.5, 4.0, 5.0, 5.0, 6.5, 6.5};

// omega_11 of the exact row, fitted (least squares) to its modes 2-8.
double exactFundamental() {
  const std::map<int, double> exact = tableRow("table5", "exact");
  double num = 0.0, den = 0.0;
  for (int mode = 2; mode <= 8; ++mode) {
    const double s = std::sqrt(kExactShape[mode - 1]);
    num += exact.at(mode) * s;
    den += s * s;
  }
  return num / den;
}

class Example7 : public ::testing::TestWithParam<Table5Case> {};

// Check 1: every entry of the model's row of Table 5 within 0.1%.
TEST_P(Example7, ReproducesTable5Within0_1Percent) {
  const Table5Case c = GetParam();
  const std::map<int, double> published = tableRow("table5", c.model);
  ASSERT_GE(published.size(), 5u) << c.model;
  const std::string json = runNamedCase(c.case_name);
  double worst = 0.0;
  for (const auto& [mode, value] : published) {
    const double omega = summaryValue(json, "omega_" + std::to_string(mode));
    ASSERT_FALSE(std::isnan(omega)) << "omega_" << mode << " missing\n" << json;
    const double error = omega / value - 1.0;
    worst = std::max(worst, std::abs(error));
    EXPECT_LT(std::abs(error), 1e-3) << "mode " << mode << ": " << omega << " vs " << value;
  }
  std::cout << "[ Table 5, " << c.model << " ] largest relative error vs the table " << worst
            << " (" << published.size() << " modes)\n";
  ::testing::Test::RecordProperty("max_relative_error_vs_table", std::to_string(worst));
}

// Check 2: the exact continuum: upper bounds (allowance 1e-4 for the printing of the exact
// figures), the degenerate (1,2)/(2,1) pair, and the fundamental within 4%.
TEST_P(Example7, ConvergesFromAboveToTheExactMembrane) {
  const Table5Case c = GetParam();
  const std::map<int, double> exact = tableRow("table5", "exact");
  const size_t modes = tableRow("table5", c.model).size();
  ASSERT_EQ(exact.size(), 8u);
  const std::string json = runNamedCase(c.case_name);
  std::ostringstream errors;
  for (const auto& [mode, value] : exact) {
    if (static_cast<size_t>(mode) > modes) break;
    const double omega = summaryValue(json, "omega_" + std::to_string(mode));
    EXPECT_GT(omega, value * (1.0 - 1e-4)) << "mode " << mode << " below the exact " << value;
    errors << " " << 100.0 * (omega / value - 1.0);
  }
  const double omega2 = summaryValue(json, "omega_2"), omega3 = summaryValue(json, "omega_3");
  EXPECT_NEAR(omega3 / omega2, 1.0, 1e-8);
  const double fundamental = summaryValue(json, "omega_1") / exactFundamental() - 1.0;
  std::cout << "[ Table 5, " << c.model << " ] error vs exact (printed row), %:" << errors.str()
            << "; fundamental vs 40.558: " << 100.0 * fundamental << " %\n";
  ::testing::Test::RecordProperty("fundamental_error_vs_exact", std::to_string(fundamental));
  EXPECT_GT(fundamental, 0.0);
  EXPECT_LT(fundamental, 0.04);
}

INSTANTIATE_TEST_SUITE_P(Table5, Example7,
                         ::testing::Values(Table5Case{"ex7-membrane-modes-9xQ8", "9 Q8", 0},
                                           Table5Case{"ex7-membrane-modes-4xQ12", "4 Q12", 0},
                                           Table5Case{"ex7-membrane-modes-4xQ8", "4 Q8", 0},
                                           Table5Case{"ex7-membrane-modes-25xQ4", "25 Q4", 5},
                                           Table5Case{"ex7-membrane-modes-16xQ4", "16 Q4", 4},
                                           Table5Case{"ex7-membrane-modes-8xT6", "8 T6", 0}),
                         flexmoor::test::CaseParamName());

// Check 3: a Q4 mesh against the closed form of its own discrete spectrum.
class Example7Q4 : public ::testing::TestWithParam<Table5Case> {};

TEST_P(Example7Q4, MatchesTheConsistentMassClosedForm) {
  const Table5Case c = GetParam();
  const int n = c.q4_divisions;
  const double h = 1.0 / n;  // on the unit square, N / (rho h) = 1 / (2 pi^2): exact omega_11 = 1
  std::vector<double> mu;
  for (int k = 1; k < n; ++k) {
    const double cosine = std::cos(k * M_PI / n);
    mu.push_back(6.0 / (h * h) * (1.0 - cosine) / (2.0 + cosine));
  }
  std::vector<double> ratios;  // omega_ij / omega_11,exact
  for (double mi : mu)
    for (double mj : mu) ratios.push_back(std::sqrt((mi + mj) / (2.0 * M_PI * M_PI)));
  std::sort(ratios.begin(), ratios.end());
  const std::string json = runNamedCase(c.case_name);
  const double omega1 = summaryValue(json, "omega_1");
  double worst_ratio = 0.0;
  for (int mode = 2; mode <= 8; ++mode) {
    const double measured = summaryValue(json, "omega_" + std::to_string(mode)) / omega1;
    const double expected = ratios[mode - 1] / ratios[0];
    worst_ratio = std::max(worst_ratio, std::abs(measured / expected - 1.0));
    EXPECT_NEAR(measured / expected, 1.0, 1e-8) << "mode " << mode;
  }
  const double scale = omega1 / (ratios[0] * exactFundamental()) - 1.0;
  std::cout << "[ Table 5, " << c.model << " ] closed form: ratios to " << worst_ratio << ", scale "
            << scale << "; closed-form omega_7 = " << ratios[6] * exactFundamental() << "\n";
  EXPECT_LT(std::abs(scale), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Table5, Example7Q4,
                         ::testing::Values(Table5Case{"ex7-membrane-modes-25xQ4", "25 Q4", 5},
                                           Table5Case{"ex7-membrane-modes-16xQ4", "16 Q4", 4}),
                         flexmoor::test::CaseParamName());

}  // namespace
