// cosinesAndSines (libhydro/waves/vector_math.hpp, one reduction and Cephes's polynomials)
// against glibc's std::cos and std::sin (correctly rounded to within 1 ulp): the absolute error
// over 200,000 arguments spread over [-4e4, 4e4] (a 3 h sea's phases reach 3e4 rad), 20,000 in
// [-4, 4] and each multiple of pi/4 up to 1e4 (the quadrants' edges). Measured at most
// 2.2e-16 in each set (one ulp of the values near 1); asserted to 4.5e-16 (2x). Beyond 2^28 std::cos and std::sin
// themselves (to the bit).
#include "libhydro/waves/vector_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace flexmoor::hydro {
namespace {

double largestError(const std::vector<double>& x) {
  std::vector<double> c(x.size()), s(x.size());
  cosinesAndSines(x.data(), c.data(), s.data(), x.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    worst = std::max({worst, std::abs(c[i] - std::cos(x[i])), std::abs(s[i] - std::sin(x[i]))});
  return worst;
}

TEST(VectorMath, CosinesAndSinesWithinAnUlpOfTheLibrary) {
  std::mt19937_64 random(3);
  const auto uniform = [&](double half) {
    return half * (2.0 * static_cast<double>(random() >> 11) * 0x1p-53 - 1.0);
  };
  std::vector<double> wide, narrow, edges;
  for (int i = 0; i < 200000; ++i) wide.push_back(uniform(4e4));
  for (int i = 0; i < 20000; ++i) narrow.push_back(uniform(4.0));
  for (int m = -12732; m <= 12732; ++m) edges.push_back(m * std::acos(-1.0) / 4.0);
  for (const std::vector<double>* x : {&wide, &narrow, &edges}) {
    const double e = largestError(*x);
    EXPECT_LT(e, 4.5e-16);
    RecordProperty("largest_error", std::to_string(e));
  }
  const std::vector<double> huge = {3e8, -1e12, 0.5};  // one past 2^28: the library for all
  std::vector<double> c(3), s(3);
  cosinesAndSines(huge.data(), c.data(), s.data(), 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(c[i], std::cos(huge[i]));
    EXPECT_EQ(s[i], std::sin(huge[i]));
  }
}

}  // namespace
}  // namespace flexmoor::hydro
