// cosinesAndSines (vector_math.hpp): both from one reduction of x to r in [-pi/4, pi/4] and
// the quadrant j mod 4 (x = j pi/2 + r), and Cephes's minimax polynomials on that interval
// (S. L. Moshier, Cephes Math Library, sin.c: sin r = r + r^3 S(r^2), cos r = 1 - r^2/2 +
// r^4 C(r^2)), in a loop the compiler vectorises (no branch, no library call). pi/2 is split
// into three parts (Cephes's DP1-DP3 times 2), the first two with trailing zero bits, so that
// j DP1 and j DP2 are exact for |j| < 2^29 and r is x - j pi/2 to about 1e-16 for |x| < 2^28.
// Compiled without -ffast-math: the rounding to the nearest integer by adding and taking away
// 1.5 2^52 must not be simplified away. Beyond 2^28 (no sea comes near: omega t of a 3 h sea
// is 3e4), std::cos and std::sin.
#include <algorithm>
#include <cmath>

#include "libhydro/waves/vector_math.hpp"

namespace flexmoor::hydro {
namespace {

constexpr double kTwoOverPi = 0.63661977236758134308;
constexpr double kRound = 6755399441055744.0;  // 1.5 2^52: x + kRound - kRound rounds x
constexpr double kDp1 = 1.57079625129699707031, kDp2 = 7.54978941586159635336e-8,
                 kDp3 = 5.39030285815811905290e-15;  // pi/2 = kDp1 + kDp2 + kDp3
constexpr double kLimit = 268435456.0;               // 2^28

}  // namespace

void cosinesAndSines(const double* __restrict x, double* __restrict c, double* __restrict s,
                     std::size_t n) {
  double largest = 0.0;
#pragma omp simd reduction(max : largest)
  for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, std::abs(x[i]));
  if (largest >= kLimit) {
    for (std::size_t i = 0; i < n; ++i) {
      c[i] = std::cos(x[i]);
      s[i] = std::sin(x[i]);
    }
    return;
  }
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    const double j = (x[i] * kTwoOverPi + kRound) - kRound;
    const double r = ((x[i] - j * kDp1) - j * kDp2) - j * kDp3;
    const double z = r * r;
    const double sin_r =
        r + r * z *
                (((((1.58962301576546568060e-10 * z - 2.50507477628578072866e-8) * z +
                    2.75573136213857245213e-6) *
                       z -
                   1.98412698295895385996e-4) *
                      z +
                  8.33333333332211858878e-3) *
                     z -
                 1.66666666666666307295e-1);
    const double cos_r = 1.0 - 0.5 * z +
                         z * z *
                             (((((-1.13585365213876817300e-11 * z + 2.08757008419747316778e-9) * z -
                                 2.75573141792967388112e-7) *
                                    z +
                                2.48015872888517045348e-5) *
                                   z -
                               1.38888888888730564116e-3) *
                                  z +
                              4.16666666666665929218e-2);
    // q = j - 4 round(j / 4) in {-2, -1, 0, 1, 2}: the quadrant (-1 for 3; -2 or 2 for 2).
    // Quadrants 1 and 3 swap sin and cos; sin is negative in 2 and 3 (q (q - 1) > 0), cos in 1
    // and 2 (q (q + 1) > 0): one comparison a choice, which the compiler makes without a
    // branch (two would keep the loop scalar).
    const double q = j - 4.0 * ((0.25 * j + kRound) - kRound);
    const bool odd = std::abs(q) == 1.0;
    const double sv = odd ? cos_r : sin_r, cv = odd ? sin_r : cos_r;
    s[i] = q * (q - 1.0) > 0.5 ? -sv : sv;
    c[i] = q * (q + 1.0) > 0.5 ? -cv : cv;
  }
}

}  // namespace flexmoor::hydro
